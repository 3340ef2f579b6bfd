// SPDX-License-Identifier: MIT
#include "panels/abuffer_panels.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "core/events.h"
#include "panels/panel_style.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {

namespace {

const algo::Color background{26, 28, 33};
const algo::Color empty_cell{40, 43, 50};  // a pixel with no fragment yet: lighter than the background, so the grid shows

// A premultiplied colour over the canvas's background.
ImU32 over_background(const glm::dvec4& c) {
    const auto channel = [&](double v, std::uint8_t b) { return std::uint8_t(std::clamp(255 * v + (1 - c.w) * b, 0.0, 255.0) + 0.5); };
    return rgb({channel(c.x, background.r), channel(c.y, background.g), channel(c.z, background.b)});
}

// The colour of sub-sample s of a pixel as its list stands: the nearest fragment covering it, or none.
std::optional<algo::Color> nearest_at(const ABufferView& v, const std::vector<algo::Fragment>& list, int s) {
    const algo::Fragment* best = nullptr;
    for (const algo::Fragment& f : list)
        if ((f.mask >> s & 1) && (!best || f.depth < best->depth)) best = &f;
    if (!best) return std::nullopt;
    return v.input->polygons[best->polygon].color;
}

// A coverage mask as an m × m grid of small squares, `size` points wide, at the cursor.
void mask_glyph(std::uint64_t mask, int m, algo::Color colour, float size) {
    ImDrawList* d = ImGui::GetWindowDrawList();
    const ImVec2 o = ImGui::GetCursorScreenPos();
    const float cell = size / float(m);
    for (int s = 0; s < m * m; ++s) {
        const ImVec2 a(o.x + float(s % m) * cell, o.y + float(s / m) * cell);
        d->AddRectFilled(a, ImVec2(a.x + cell - 1, a.y + cell - 1), (mask >> s & 1) ? rgb(colour) : IM_COL32(60, 63, 70, 255));
    }
    ImGui::Dummy(ImVec2(size, size));
}

// The open pixel's fragment list at the cursor: each fragment's mask and numbers, the one resolving now in yellow,
// the pixel's colour once resolved. Its lines wrap at the window's wrap position.
void fragment_list(const ABufferView& v, std::optional<std::pair<int, int>> selected) {
    const int m = v.input->mask_size;
    const auto n = [](auto value) { return std::to_string(value); };
    const auto f = [](double value) { return algo::format_number(value); };
    const int px = selected ? selected->first : v.x, py = selected ? selected->second : v.y;
    if (px < 0) return;
    const std::vector<algo::Fragment>& list = v.lists[v.at(px, py)];
    ImGui::TextWrapped("%s", tr(selected ? "abuffer.selected" : "abuffer.pixel", {{"x", n(px)}, {"y", n(py)}, {"count", n(list.size())}}).c_str());
    for (std::size_t k = 0; k < list.size(); ++k) {
        const algo::Fragment& fr = list[k];
        mask_glyph(fr.mask, m, v.input->polygons[fr.polygon].color, ImGui::GetTextLineHeight() * 2);
        ImGui::SameLine();
        const bool current = v.fragment && v.fragment->x == px && v.fragment->y == py && v.fragment->order == k;
        const std::string line = tr("abuffer.fragment", {{"polygon", n(fr.polygon)}, {"depth", f(fr.depth)}, {"alpha", f(fr.opacity)},
                                                         {"covered", n(std::popcount(fr.mask))}, {"bits", n(m * m)}});
        if (current) ImGui::TextColored(ImVec4(0.94f, 0.89f, 0.26f, 1), "%s", line.c_str());
        else ImGui::TextUnformatted(line.c_str());
    }
    if (v.resolved[v.at(px, py)]) {
        const glm::dvec4 c = v.rgba[v.at(px, py)];
        ImGui::TextWrapped("%s", tr("abuffer.resolved", {{"coverage", f(std::round(1000 * c.w) / 10)}, {"r", f(c.x)}, {"g", f(c.y)}, {"b", f(c.z)}}).c_str());
    }
    if (v.fragment && v.fragment->x == px && v.fragment->y == py)
        ImGui::TextWrapped("%s", tr("abuffer.shown", {{"shown", n(v.fragment->shown)}, {"covered", n(v.fragment->covered)},
                                                      {"percent", f(std::round(1000 * v.fragment->weight) / 10)}}).c_str());
}

}  // namespace

FatGrid abuffer_grid(const ABufferSession& s, float x, float y, float w, float h) {
    const algo::Viewport vp = s.view().input->viewport;
    const float margin = 24, title = ImGui::GetTextLineHeightWithSpacing() + 4;
    // the A-buffer's grid and, below it at a third of its size, the one-sample image
    const float cell = std::max(2.0f, std::min((w - 2 * margin) / float(vp.width), (h - 3 * margin - 2 * title) / (float(vp.height) * 4 / 3)));
    return {x + margin, y + margin + title, cell};
}

bool abuffer_canvas(const ABufferSession& s, std::optional<std::pair<int, int>> selected, float x, float y, float w, float h) {
    const ABufferView& v = s.view();
    const algo::Viewport vp = v.input->viewport;
    const int m = v.input->mask_size;
    ImDrawList* d = begin_canvas("##abuffer canvas", x, y, w, h);
    const FatGrid g = abuffer_grid(s, x, y, w, h);
    const float cell = g.cell, title = ImGui::GetTextLineHeightWithSpacing() + 4;
    const ImVec2 o(g.x0, g.y0);
    d->AddText(ImVec2(o.x, o.y - title), IM_COL32(220, 220, 220, 255),
               tr("abuffer.grid", {{"m", std::to_string(m)}, {"bits", std::to_string(m * m)}}).c_str());
    for (int py = 0; py < vp.height; ++py)
        for (int px = 0; px < vp.width; ++px) {
            const std::size_t k = v.at(px, py);
            const ImVec2 a(o.x + float(px) * cell, o.y + float(py) * cell), b(a.x + cell - 1, a.y + cell - 1);
            if (v.resolved[k]) {
                d->AddRectFilled(a, b, over_background(v.rgba[k]));
                continue;
            }
            d->AddRectFilled(a, b, rgb(empty_cell));
            if (v.lists[k].empty()) continue;
            const float sub = (cell - 1) / float(m);  // each sub-sample: the nearest fragment's colour so far
            for (int s2 = 0; s2 < m * m; ++s2)
                if (const auto c = nearest_at(v, v.lists[k], s2)) {
                    const ImVec2 p(a.x + float(s2 % m) * sub, a.y + float(s2 / m) * sub);
                    d->AddRectFilled(ImVec2(p.x + sub * 0.2f, p.y + sub * 0.2f), ImVec2(p.x + sub * 0.8f, p.y + sub * 0.8f), rgb(*c));
                }
        }
    grid_numbers(d, o, cell, vp);
    for (const algo::ScreenPolygon& p : v.input->polygons)
        outline(d, o, cell, p, v.polygon >= 0 && &p == &v.input->polygons[std::size_t(v.polygon)] ? okabe_ito_u32(algo::okabe_ito::yellow) : IM_COL32(220, 220, 220, 90),
                canvas_px(v.polygon >= 0 && &p == &v.input->polygons[std::size_t(v.polygon)] ? 2.5f : 1));
    const auto frame = [&](int px, int py, ImU32 colour, float width) {
        d->AddRect(ImVec2(o.x + float(px) * cell - 2, o.y + float(py) * cell - 2), ImVec2(o.x + float(px + 1) * cell + 1, o.y + float(py + 1) * cell + 1),
                   colour, 0, 0, canvas_px(width));
    };
    if (v.x >= 0) frame(v.x, v.y, okabe_ito_u32(algo::okabe_ito::yellow), 3);
    if (selected) frame(selected->first, selected->second, IM_COL32(255, 255, 255, 255), 2);

    // the same image with one sample per pixel (the z-buffer's coverage), beside it
    const float small = cell / 3;
    const ImVec2 one(o.x, o.y + cell * float(vp.height) + 24 + title);
    d->AddText(ImVec2(one.x, one.y - title), IM_COL32(220, 220, 220, 255), tr("abuffer.one_sample").c_str());
    for (int py = 0; py < vp.height; ++py)
        for (int px = 0; px < vp.width; ++px)
            d->AddRectFilled(ImVec2(one.x + float(px) * small, one.y + float(py) * small), ImVec2(one.x + float(px + 1) * small, one.y + float(py + 1) * small),
                             over_background(v.input->one_sample[v.at(px, py)]));

    // the open pixel's list beside it, in the view's free lower right: eight lines of text and three masks fit there
    // at every size the window scales to, or the list stays in the state box
    const float right_margin = canvas_px(16);
    const float beside = std::max(small * float(vp.width), ImGui::CalcTextSize(tr("abuffer.one_sample").c_str()).x);
    const float list_x = one.x + beside + canvas_px(32), list_top = one.y - title;
    const float line = ImGui::GetTextLineHeightWithSpacing();
    const bool room = x + w - right_margin - list_x >= 22 * ImGui::GetFontSize() && y + h - list_top >= 8.5f * line;
    if (room) {
        ImGui::SetCursorScreenPos(ImVec2(list_x, list_top));
        ImGui::BeginGroup();  // its lines start at list_x, not at the canvas's left
        ImGui::PushTextWrapPos(x + w - right_margin - ImGui::GetWindowPos().x);
        fragment_list(v, selected);
        ImGui::PopTextWrapPos();
        ImGui::EndGroup();
    }
    ImGui::End();
    return room;
}

void abuffer_state_panel(const ABufferSession& s, std::optional<std::pair<int, int>> selected, bool list_in_view, const PanelLayout& l) {
    begin_column_box(l, Box::state, (tr("abuffer.title") + "###state").c_str());
    const ABufferView& v = s.view();
    const auto n = [](auto value) { return std::to_string(value); };
    if (!list_in_view) {
        ImGui::PushTextWrapPos(0);
        fragment_list(v, selected);
        ImGui::PopTextWrapPos();
    }
    wrapped_text(tr("abuffer.counts", {{"fragments", n(v.fragments)}, {"pixels", n(v.pixels_resolved)}}));
    const float need = column_box_height_so_far();  // the rule under the facts: what scrolls in a short column
    wrapped_text(tr("abuffer.rule"), dim_text);
    end_column_box(l, Box::state, need);
}

}  // namespace hsr::viz
