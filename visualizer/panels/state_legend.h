// SPDX-License-Identifier: MIT
// A legend for a view whose colours carry meaning: a swatch and its word for each state, as many to a row as fit.
#pragma once

#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include <imgui.h>

#include "panels/panel_style.h"
#include "state/label_placement.h"
#include "state/state_colours.h"
#include "state/strings.h"

namespace hsr::viz {

inline ImVec4 colour_of(const StateColour& c, float alpha = 1) { return ImVec4(c.r, c.g, c.b, alpha); }

// A square of the colour, outlined so that a dark one shows on the dark background.
inline void swatch(ImDrawList* d, ImVec2 at, float side, const StateColour& c) {
    d->AddRectFilled(at, ImVec2(at.x + side, at.y + side), ImGui::GetColorU32(colour_of(c)));
    d->AddRect(at, ImVec2(at.x + side, at.y + side), IM_COL32(200, 203, 210, 255));
}

inline void state_legend(std::span<const StateColour> entries) {
    const float right_edge = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    const float side = ImGui::GetTextLineHeight() * 0.8f;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const std::string word = tr(std::string(entries[i].legend));
        const float width = side + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(word.c_str()).x;
        if (i > 0) {
            ImGui::SameLine(0, ImGui::GetStyle().ItemSpacing.x * 2);
            if (ImGui::GetCursorScreenPos().x + width > right_edge) ImGui::NewLine();
        }
        const ImVec2 at = ImGui::GetCursorScreenPos();
        swatch(ImGui::GetWindowDrawList(), ImVec2(at.x, at.y + (ImGui::GetTextLineHeight() - side) / 2), side, entries[i]);
        ImGui::Dummy(ImVec2(side, ImGui::GetTextLineHeight()));
        ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
        ImGui::TextUnformatted(word.c_str());
    }
}

// The same drawn on a canvas, in one row whose bottom-left corner is (x, bottom); its height is legend_height().
inline float legend_height() { return ImGui::GetTextLineHeight() * 1.6f; }
inline void canvas_legend(ImDrawList* d, float x, float bottom, std::span<const StateColour> entries) {
    const float side = ImGui::GetTextLineHeight() * 0.8f, line = ImGui::GetTextLineHeight();
    const float top = bottom - legend_height() + (legend_height() - line) / 2;
    for (const StateColour& e : entries) {
        const std::string word = tr(std::string(e.legend));
        swatch(d, ImVec2(x, top + (line - side) / 2), side, e);
        d->AddText(ImVec2(x + side + 6, top), IM_COL32(200, 203, 210, 255), word.c_str());
        x += side + 6 + ImGui::CalcTextSize(word.c_str()).x + 2 * line;
    }
}

// The same in the 3D view's lower left corner, on a dark backing, in as many rows as the view's width needs: over
// the scene, under the windows. Its rectangle, for the screen's SceneFrame::covered, so that no label of the scene
// lands on it.
inline float legend_entry_width(const StateColour& e) {
    return ImGui::GetTextLineHeight() * 0.8f + 6 + ImGui::CalcTextSize(tr(std::string(e.legend)).c_str()).x;
}
// The entries of each row, left to right, within `width` points.
inline std::vector<std::vector<StateColour>> legend_rows(std::span<const StateColour> entries, float width) {
    std::vector<std::vector<StateColour>> rows(1);
    float x = 0;
    const float gap = 2 * ImGui::GetTextLineHeight();
    for (const StateColour& e : entries) {
        const float w = legend_entry_width(e);
        if (!rows.back().empty() && x + gap + w > width) rows.emplace_back(), x = 0;
        x += (rows.back().empty() ? 0 : gap) + w;
        rows.back().push_back(e);
    }
    return rows;
}
inline ViewRect view_legend_rect(float view_w, float view_h, std::span<const StateColour> entries) {
    constexpr float margin = 12, pad = 6;
    const auto rows = legend_rows(entries, view_w - 2 * margin - 2 * pad);
    float widest = 0;
    for (const auto& row : rows) {
        float w = 0;
        for (const StateColour& e : row) w += (w > 0 ? 2 * ImGui::GetTextLineHeight() : 0) + legend_entry_width(e);
        widest = std::max(widest, w);
    }
    return {margin - pad, view_h - margin - float(rows.size()) * legend_height() - pad, margin + widest + pad, view_h - margin + pad};
}
inline void view_legend(float view_w, float view_h, std::span<const StateColour> entries) {
    if (entries.empty()) return;
    const ViewRect r = view_legend_rect(view_w, view_h, entries);
    ImDrawList* d = ImGui::GetBackgroundDrawList();
    d->AddRectFilled(ImVec2(r.left, r.top), ImVec2(r.right, r.bottom), IM_COL32(20, 22, 26, 220), 4);
    float bottom = r.top + 6;
    for (const auto& row : legend_rows(entries, view_w - 2 * 12 - 2 * 6)) {
        bottom += legend_height();
        canvas_legend(d, r.left + 6, bottom, row);
    }
}

}  // namespace hsr::viz
