// SPDX-License-Identifier: MIT
// A legend for a view whose colours carry meaning: a swatch and its word for each state, as many to a row as fit.
#pragma once

#include <span>
#include <string>

#include <imgui.h>

#include "panels/panel_style.h"
#include "state/state_colours.h"
#include "state/strings.h"

namespace hsr::viz {

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
        const float top = at.y + (ImGui::GetTextLineHeight() - side) / 2;
        ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(at.x, top), ImVec2(at.x + side, top + side),
                                                  ImGui::GetColorU32(ImVec4(entries[i].r, entries[i].g, entries[i].b, 1)));
        ImGui::GetWindowDrawList()->AddRect(ImVec2(at.x, top), ImVec2(at.x + side, top + side), IM_COL32(200, 203, 210, 255));
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
        const float box_top = top + (line - side) / 2;
        d->AddRectFilled(ImVec2(x, box_top), ImVec2(x + side, box_top + side), ImGui::GetColorU32(ImVec4(e.r, e.g, e.b, 1)));
        d->AddRect(ImVec2(x, box_top), ImVec2(x + side, box_top + side), IM_COL32(200, 203, 210, 255));
        d->AddText(ImVec2(x + side + 6, top), IM_COL32(200, 203, 210, 255), word.c_str());
        x += side + 6 + ImGui::CalcTextSize(word.c_str()).x + 2 * line;
    }
}

}  // namespace hsr::viz
