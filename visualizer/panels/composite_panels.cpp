// SPDX-License-Identifier: MIT
#include "panels/composite_panels.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include <imgui.h>

#include "core/events.h"
#include "core/overloaded.h"
#include "panels/panel_style.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {

namespace {

using algo::Rgba;

constexpr ImU32 over_colour = IM_COL32(245, 200, 70, 255);    // amber: back to front
constexpr ImU32 under_colour = IM_COL32(90, 200, 240, 255);   // sky blue: front to back
constexpr ImU32 text_colour = IM_COL32(225, 225, 225, 255);
constexpr ImU32 dim_colour = IM_COL32(160, 163, 170, 255);

// "(1, .25, .25, .5)": two places at most, as the notes write (.5, .5, .5, .5), so that a layer's numbers fit
// under its swatch
std::string two_places(Rgba c) {
    const auto n = [](double v) {
        char b[16];
        std::snprintf(b, sizeof b, "%.2f", v);
        std::string t = b;
        while (t.back() == '0') t.pop_back();
        if (t.back() == '.') t.pop_back();
        if (t.starts_with("0.")) t.erase(0, 1);
        return t.empty() || t == "-0" ? std::string("0") : t;
    };
    return "(" + n(c.r) + ", " + n(c.g) + ", " + n(c.b) + ", " + n(c.a) + ")";
}

ImU32 straight_colour(Rgba c) {  // ImGui blends straight alpha: glass over what is drawn below
    const auto q = [](double v) { return int(std::clamp(v, 0.0, 1.0) * 255 + 0.5); };
    return IM_COL32(q(c.r), q(c.g), q(c.b), q(c.a));
}

// A checkerboard, so that what is see-through shows as such.
void checkerboard(ImDrawList* d, ImVec2 p, float size) {
    const int n = 8;
    const float s = size / n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            d->AddRectFilled(ImVec2(p.x + float(i) * s, p.y + float(j) * s), ImVec2(p.x + float(i + 1) * s, p.y + float(j + 1) * s),
                             (i + j) % 2 ? IM_COL32(150, 150, 150, 255) : IM_COL32(95, 95, 95, 255));
}

// A swatch of a straight colour over the checkerboard, with lines of text under it; returns the text's bottom.
float swatch(ImDrawList* d, ImVec2 p, float size, Rgba straight, std::initializer_list<std::pair<std::string, ImU32>> lines,
             ImU32 outline = 0) {
    checkerboard(d, p, size);
    d->AddRectFilled(p, ImVec2(p.x + size, p.y + size), straight_colour(straight));
    if (outline) d->AddRect(ImVec2(p.x - 3, p.y - 3), ImVec2(p.x + size + 3, p.y + size + 3), outline, 0, 0, canvas_px(3));
    float y = p.y + size + canvas_px(4);
    for (const auto& [text, colour] : lines) {
        d->AddText(ImVec2(p.x, y), colour, text.c_str());
        y += ImGui::GetTextLineHeight();
    }
    return y;
}

// Porter and Duff's picture of an operator: A covers the left α_A of the square, B the top α_B, so both cover
// α_A · α_B (their shapes uncorrelated); each of the four regions shows A, B, both summed, or nothing.
void coverage_square(ImDrawList* d, ImVec2 p, float size, const algo::PorterDuffApplied& e, Rgba a_colour, Rgba b_colour) {
    using algo::PorterDuff;
    checkerboard(d, p, size);
    const float xa = p.x + float(e.a.a) * size, yb = p.y + float(e.b.a) * size;
    const Rgba a{a_colour.r, a_colour.g, a_colour.b, 1}, b{b_colour.r, b_colour.g, b_colour.b, 1};
    const Rgba sum{std::min(1.0, a.r + b.r), std::min(1.0, a.g + b.g), std::min(1.0, a.b + b.b), 1};
    const auto fill = [&](float x0, float y0, float x1, float y1, const Rgba* c) {
        if (c && x1 > x0 && y1 > y0) d->AddRectFilled(ImVec2(x0, y0), ImVec2(x1, y1), straight_colour(*c));
    };
    const Rgba *both = nullptr, *a_only = nullptr, *b_only = nullptr;
    switch (e.op) {
        case PorterDuff::clear: break;
        case PorterDuff::a: both = a_only = &a; break;
        case PorterDuff::b: both = b_only = &b; break;
        case PorterDuff::over: both = a_only = &a, b_only = &b; break;
        case PorterDuff::in: both = &a; break;
        case PorterDuff::out: a_only = &a; break;
        case PorterDuff::atop: both = &a, b_only = &b; break;
        case PorterDuff::xor_: a_only = &a, b_only = &b; break;
        case PorterDuff::plus: both = &sum, a_only = &a, b_only = &b; break;
    }
    fill(p.x, p.y, xa, yb, both);
    fill(p.x, yb, xa, p.y + size, a_only);
    fill(xa, p.y, p.x + size, yb, b_only);
    d->AddRect(p, ImVec2(p.x + size, p.y + size), IM_COL32(230, 230, 230, 160));
}

// An operator's F_A and F_B as Porter and Duff's table gives them (the step's line shows the current operator's).
std::pair<std::string, std::string> factors_in_words(algo::PorterDuff op) {
    static constexpr const char* factors[][2] = {{"0", "0"},         {"1", "0"},         {"0", "1"},
                                                 {"1", "1 − α_A"},   {"α_B", "0"},       {"1 − α_B", "0"},
                                                 {"α_B", "1 − α_A"}, {"1 − α_B", "1 − α_A"}, {"1", "1"}};
    const auto ops = algo::porter_duff_operators();
    for (std::size_t k = 0; k < ops.size() && k < std::size(factors); ++k)
        if (ops[k] == op) return {factors[k][0], factors[k][1]};
    return {"?", "?"};
}

}  // namespace

void composite_canvas(const CompositeSession& s, float x, float y, float w, float h) {
    const CompositeView& v = s.view();
    const auto& layers = *v.layers;
    ImDrawList* d = begin_canvas("##composite canvas", x, y, w, h);
    const float margin = canvas_px(24), line = ImGui::GetTextLineHeight(), gap = canvas_px(16);
    const float left = x + margin, usable = w - 2 * margin;
    float top = y + margin;
    d->AddText(ImVec2(left, top), text_colour, tr("composite.layers_title").c_str());
    top += line + canvas_px(8);
    const std::size_t n = std::max<std::size_t>(1, layers.size());
    // Three rows of swatches share the height: the layers, the two composites, the operators
    const float text_rows = 3 * line + canvas_px(8);
    const float size = std::max(canvas_px(24), std::min({(usable - gap * float(n - 1)) / float(n) * 0.8f, (h - 2 * margin) / 3 - text_rows - line,
                                                          canvas_px(150)}));
    const float column = std::max(size, (usable - gap * float(n - 1)) / float(n)) + gap;
    float bottom = top;
    if (layers.empty()) wrapped_text(tr("composite.no_layers"));
    for (std::size_t i = 0; i < layers.size(); ++i) {
        const algo::Layer& l = layers[i];
        const ImU32 outline = int(i) == v.over_layer && !v.compared && v.under_layer < 0 ? over_colour
                              : int(i) == v.under_layer && !v.compared                  ? under_colour
                                                                                        : 0;
        const bool skipped = v.stopped && i >= v.stopped->layer;
        char head[96];
        std::snprintf(head, sizeof head, "%s %zu (#%u) · α = %.3g", tr("composite.layer").c_str(), i, unsigned(l.id), l.colour.a);
        const std::string pre = i < v.premultiplied.size() ? "→ " + two_places(v.premultiplied[i]) : "";
        const ImVec2 at(left + float(i) * column, top);
        bottom = std::max(bottom, swatch(d, at, size, l.colour,
                                         {{head, text_colour}, {two_places(l.colour), dim_colour}, {pre, text_colour}}, outline));
        if (skipped) {  // left out by the early stop
            d->AddLine(at, ImVec2(at.x + size, at.y + size), under_colour, canvas_px(3));
            d->AddLine(ImVec2(at.x + size, at.y), ImVec2(at.x, at.y + size), under_colour, canvas_px(3));
        }
    }
    // The two composites so far
    top = bottom + gap;
    const Rgba btf = algo::unpremultiply(v.back_to_front), ftb = algo::unpremultiply(v.front_to_back);
    const std::string btf_head = tr("composite.back_to_front"), ftb_head = tr("composite.front_to_back");
    bottom = std::max(swatch(d, ImVec2(left, top), size, btf,
                             {{btf_head, over_colour}, {two_places(v.back_to_front), text_colour},
                              {tr("composite.straight", {{"colour", two_places(v.straight)}}), dim_colour}}),
                      swatch(d, ImVec2(left + std::max(column, usable / 2), top), size, ftb,
                             {{ftb_head, under_colour}, {two_places(v.front_to_back), text_colour},
                              {v.stopped ? tr("composite.stopped", {{"skipped", std::to_string(v.stopped->skipped)}}) : "", dim_colour}}));
    // Porter and Duff's operators on the two nearest layers, as they are applied
    if (!v.porter_duff.empty() && layers.size() >= 2) {
        top = bottom + gap;
        const float cell = std::max(canvas_px(20), std::min((usable - gap * 8) / 9, y + h - margin - top - 2 * line - canvas_px(4)));
        for (std::size_t k = 0; k < v.porter_duff.size(); ++k) {
            const algo::PorterDuffApplied& e = v.porter_duff[k];
            const ImVec2 at(left + float(k) * (cell + gap), top);
            coverage_square(d, at, cell, e, layers[0].colour, layers[1].colour);
            char alpha[32];
            std::snprintf(alpha, sizeof alpha, "α = %.3g", e.result.a);
            d->AddText(ImVec2(at.x, at.y + cell + canvas_px(4)), text_colour, algo::expression(e.op).c_str());
            d->AddText(ImVec2(at.x, at.y + cell + canvas_px(4) + line), dim_colour, alpha);
        }
    }
    ImGui::End();
}

void composite_state_panel(const CompositeSession& s, const PanelLayout& l) {
    begin_column_box(l, Box::state, (tr("composite.title") + "###state").c_str());
    const CompositeView& v = s.view();
    const auto c = [](Rgba x) { return algo::format_rgba(x); };
    const auto f = [](double x) { return algo::format_number(x); };
    if (v.last)
        std::visit(overloaded{
                       [&](const algo::LayersFound&) { wrapped_text(tr("composite.rule"), dim_text); },
                       [&](const algo::LayerPremultiplied& e) {
                           wrapped_text("(r, g, b, α) = " + c(e.straight));
                           wrapped_text("(αr, αg, αb, α) = " + c(e.premultiplied));
                       },
                       [&](const algo::OverApplied& e) {
                           wrapped_text("C′ = C_F + (1 − A_F)·C", dim_text);
                           wrapped_text("= " + c(e.front) + " + " + f(1 - e.front.a) + "·" + c(e.before));
                           wrapped_text("= " + c(e.after));
                           wrapped_text(tr("composite.straight_formula"), dim_text);
                           wrapped_text("= " + c(e.straight_after));
                       },
                       [&](const algo::UnderApplied& e) {
                           wrapped_text("C′ = C + (1 − A)·C_F", dim_text);
                           wrapped_text("= " + c(e.before) + " + " + f(1 - e.before.a) + "·" + c(e.back));
                           wrapped_text("= " + c(e.after));
                       },
                       [&](const algo::EarlyStop& e) {
                           wrapped_text(tr("composite.stop", {{"alpha", f(e.alpha)}, {"skipped", std::to_string(e.skipped)}}));
                       },
                       [&](const algo::OrdersCompared& e) {
                           wrapped_text(tr("composite.orders", {{"back", c(e.back_to_front)}, {"front", c(e.front_to_back)},
                                                                {"difference", f(e.difference)}}));
                       },
                       [&](const algo::AssociativityChecked& e) {
                           wrapped_text("(F over M) over B = " + c(e.left));
                           wrapped_text("F over (M over B) = " + c(e.right));
                           wrapped_text(tr("composite.naive"), dim_text);
                           wrapped_text("(F · M) · B = " + c(e.naive_left));
                           wrapped_text("F · (M · B) = " + c(e.naive_right));
                       },
                       [&](const algo::PorterDuffApplied& e) {
                           const auto [fa, fb] = factors_in_words(e.op);
                           wrapped_text(algo::expression(e.op) + " = F_A·A + F_B·B,  F_A = " + fa + ",  F_B = " + fb, dim_text);
                           wrapped_text("= " + f(e.fa) + "·" + c(e.a) + " + " + f(e.fb) + "·" + c(e.b));
                           wrapped_text("= " + c(e.result));
                       },
                       [&](const algo::CompositeFinished& e) {
                           wrapped_text(tr("composite.done", {{"colour", c(e.colour)}, {"straight", c(e.straight)}}));
                       },
                   },
                   *v.last);
    else
        wrapped_text(tr("composite.rule"), dim_text);
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
