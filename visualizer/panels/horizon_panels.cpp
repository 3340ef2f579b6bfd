// SPDX-License-Identifier: MIT
#include "panels/horizon_panels.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <utility>
#include <vector>

#include <imgui.h>

#include "core/events.h"
#include "panels/panel_style.h"
#include "panels/wrapped_text.h"
#include "state/horizon_colours.h"
#include "state/strings.h"

namespace hsr::viz {

namespace {

constexpr ImU32 upper_colour = IM_COL32(245, 200, 70, 255);   // amber
constexpr ImU32 lower_colour = IM_COL32(90, 200, 240, 255);   // sky blue
constexpr ImU32 hidden_colour = IM_COL32(120, 124, 132, 110);
constexpr ImU32 current_colour = IM_COL32(255, 255, 255, 255);

// A curve's colour by its depth: the nearest green, the farthest violet (so rows far apart are told apart).
ImU32 curve_colour(int row, int rows) {
    const algo::Color c = horizon_curve_colour(row, rows);
    return IM_COL32(c.r, c.g, c.b, 255);
}

// Where the canvas draws screen column c (its centre) and screen height y.
struct ScreenMap {
    float left, top, width, height;
    int columns;
    double y_min, y_max;
    float x(double column_centre) const { return left + float(column_centre / columns) * width; }
    float y(double screen_y) const { return top + height - float((screen_y - y_min) / (y_max - y_min)) * height; }
};

}  // namespace

void horizon_canvas(const HorizonSession& s, float x, float y, float w, float h) {
    const HorizonView& v = s.view();
    ImDrawList* d = begin_canvas("##horizon canvas", x, y, w, h);
    const float margin = canvas_px(28), line = ImGui::GetTextLineHeightWithSpacing();
    float axis = 0;  // the y values on the left: as wide as the widest
    for (const double value : {v.y_min, v.y_max}) axis = std::max(axis, ImGui::CalcTextSize(algo::format_number(value).c_str()).x + canvas_px(6));
    // The legend under the screen, in as many lines as the width needs (German words are long)
    struct Key {
        ImU32 colour;
        std::string text;
    };
    const std::vector<Key> keys = {{upper_colour, tr("horizon.upper")}, {lower_colour, tr("horizon.lower")},
                                   {curve_colour(0, 2), tr("horizon.shown")}, {hidden_colour, tr("horizon.hidden")}};
    const float swatch = canvas_px(28), gap = canvas_px(12), legend_w = w - 2 * margin - axis;
    std::vector<ImVec2> key_at;  // relative to the legend's top left
    for (float kx = 0, ky = 0; const Key& k : keys) {
        const float kw = swatch + ImGui::CalcTextSize(k.text.c_str()).x;
        if (kx > 0 && kx + kw > legend_w) kx = 0, ky += line;
        key_at.emplace_back(kx, ky);
        kx += kw + gap;
    }
    const float legend_h = key_at.back().y + line;
    const float small = axis_number_size(), numbers_h = small + canvas_px(2);  // the columns' numbers under the screen
    const ScreenMap map{x + margin + axis, y + margin + line, legend_w, h - 2 * margin - line - legend_h - numbers_h - canvas_px(6), v.columns,
                        v.y_min, v.y_max};
    const int rows = v.terrain->rows;
    // The canvas's own background: the terrain's 3D view beside it must not show through its margins
    d->AddRectFilled(ImVec2(x, y), ImVec2(x + w, y + h), IM_COL32(26, 28, 33, 255));  // palette::background
    d->AddRectFilled(ImVec2(map.left, map.top), ImVec2(map.left + map.width, map.top + map.height), IM_COL32(22, 24, 30, 255));
    d->AddText(ImVec2(map.left, map.top - line), IM_COL32(220, 220, 220, 255), tr("horizon.screen", {{"columns", std::to_string(v.columns)}}).c_str());
    if (v.columns <= 128) {  // the screen's columns, faintly, and their numbers under it (the questions name them)
        for (int c = 0; c <= v.columns; ++c) {
            const float px = map.x(c);
            d->AddLine(ImVec2(px, map.top), ImVec2(px, map.top + map.height), IM_COL32(60, 64, 72, 120));
        }
        ImFont* font = ImGui::GetFont();
        const int step = axis_number_step(map.width / float(v.columns));
        for (int c = 0; c < v.columns; c += step) {
            const std::string t = std::to_string(c);
            d->AddText(font, small, ImVec2(map.x(c + 0.5) - font->CalcTextSizeA(small, 1e9f, 0, t.c_str()).x / 2, map.top + map.height + 1),
                       IM_COL32(170, 170, 170, 255), t.c_str());
        }
    }
    // The horizons first, as wide translucent step lines across their columns, so that the curve that set them
    // still shows on top
    const auto horizon = [&](const std::vector<double>& values, ImU32 colour) {
        for (int c = 0; c < v.columns; ++c) {
            const double value = values[std::size_t(c)];
            if (!std::isfinite(value)) continue;
            d->AddLine(ImVec2(map.x(c), map.y(value)), ImVec2(map.x(c + 1), map.y(value)), colour, canvas_px(6));
        }
    };
    horizon(v.upper, (upper_colour & 0x00ffffffu) | 0x90000000u);
    horizon(v.lower, (lower_colour & 0x00ffffffu) | 0x90000000u);
    // The curves drawn so far: bright where a point and its neighbour showed, faint where either was hidden
    const bool many = std::size_t(rows) * std::size_t(v.columns) > 200'000;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c + 1 < v.columns; ++c) {
            const std::size_t a = v.at(r, c), b = v.at(r, c + 1);
            if (!v.tested[a] || !v.tested[b]) continue;
            const bool shown = v.sight[a] != algo::Sight::hidden && v.sight[b] != algo::Sight::hidden;
            if (!shown && many) continue;
            const ImVec2 p(map.x(c + 0.5), map.y(v.y[a])), q(map.x(c + 1.5), map.y(v.y[b]));
            d->AddLine(p, q, shown ? curve_colour(r, rows) : hidden_colour, canvas_px(shown ? 2.5f : 1.0f));
        }
    // The screen's y at its bottom, top and 0, on the left
    for (const double value : {v.y_min, v.y_max, 0.0}) {
        if (value < v.y_min || value > v.y_max || (value == 0 && (v.y_min == 0 || v.y_max == 0))) continue;
        char short_value[24];  // three digits: the axis's ends, not a computation's ("3.73", not "3.73205")
        std::snprintf(short_value, sizeof short_value, "%.3g", value);
        const std::string text = short_value;
        const float ty = std::clamp(map.y(value) - line / 2, map.top, map.top + map.height - line);
        d->AddText(ImVec2(map.left - ImGui::CalcTextSize(text.c_str()).x - canvas_px(4), ty), IM_COL32(170, 170, 170, 255), text.c_str());
    }
    // The point tested last: its column, and a ring green where it showed, red where it was hidden
    if (v.last) {
        const algo::PointTested& e = *v.last;
        const float px = map.x(e.column + 0.5), py = map.y(e.y);
        d->AddRect(ImVec2(map.x(e.column), map.top), ImVec2(map.x(e.column + 1), map.top + map.height), IM_COL32(255, 255, 255, 70), 0, 0, canvas_px(1));
        const ImU32 ring = e.sight == algo::Sight::hidden ? IM_COL32(240, 80, 60, 255) : IM_COL32(90, 220, 130, 255);
        if (!e.first)  // the horizons it was tested against, before it moved them: ticks on its column
            for (const auto& [value, colour] : {std::pair{e.upper, upper_colour}, std::pair{e.lower, lower_colour}})
                d->AddLine(ImVec2(map.x(e.column) - canvas_px(6), map.y(value)), ImVec2(map.x(e.column + 1) + canvas_px(6), map.y(value)), colour,
                           canvas_px(2));
        d->AddCircle(ImVec2(px, py), canvas_px(7), ring, 0, canvas_px(3));
        d->AddCircleFilled(ImVec2(px, py), canvas_px(2.5f), current_colour);
    }
    const ImVec2 legend(map.left, map.top + map.height + numbers_h + canvas_px(6));
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const ImVec2 at(legend.x + key_at[k].x, legend.y + key_at[k].y);
        d->AddLine(ImVec2(at.x, at.y + line / 2), ImVec2(at.x + canvas_px(22), at.y + line / 2), keys[k].colour, canvas_px(3));
        d->AddText(ImVec2(at.x + swatch, at.y), IM_COL32(220, 220, 220, 255), keys[k].text.c_str());
    }
    ImGui::End();
}

void horizon_state_panel(const HorizonSession& s, const PanelLayout& l) {
    begin_column_box(l, Box::state, (tr("horizon.title") + "###state").c_str());
    const HorizonView& v = s.view();
    const auto n = [](auto value) { return std::to_string(value); };
    const auto f = [](double value) { return algo::format_number(value); };
    wrapped_text(tr("horizon.rule", {{"elevation", f(v.terrain->elevation)}}), dim_text);
    if (v.last) {
        const algo::PointTested& e = *v.last;
        wrapped_text(tr("horizon.point", {{"row", n(e.row)}, {"column", n(e.column)}, {"y", f(e.y)}}));
        if (e.first) wrapped_text(tr("horizon.first"));
        else wrapped_text(tr("horizon.bounds", {{"upper", f(e.upper)}, {"lower", f(e.lower)}}));
        wrapped_text(tr(e.sight == algo::Sight::above ? "horizon.is_above" : e.sight == algo::Sight::below ? "horizon.is_below" : "horizon.is_hidden"));
    } else if (v.row >= 0) {
        wrapped_text(tr("horizon.curve", {{"row", n(v.row)}}));
    }
    wrapped_text(tr("horizon.counts", {{"drawn", n(v.curves_drawn)}, {"rows", n(v.terrain->rows)}, {"visible", n(v.visible)}, {"hidden", n(v.hidden)}}));
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
