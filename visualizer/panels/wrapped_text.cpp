// SPDX-License-Identifier: MIT
#include "panels/wrapped_text.h"

#include <algorithm>

#include "panels/layout_audit.h"

namespace hsr::viz {

void wrapped_text(std::string_view text) {
    const float width = std::max(ImGui::GetContentRegionAvail().x, 1.0f);
    int broken = 0;
    for (const std::string& line : wrap_at_spaces(
             text, width, [](std::string_view s) { return ImGui::CalcTextSize(s.data(), s.data() + s.size()).x; }, &broken))
        ImGui::TextUnformatted(line.c_str());
    if (broken) note_broken_word();
}

float wrapped_height(std::string_view text) {
    const float width = std::max(ImGui::GetContentRegionAvail().x, 1.0f);
    const auto lines = wrap_at_spaces(text, width, [](std::string_view s) { return ImGui::CalcTextSize(s.data(), s.data() + s.size()).x; });
    return float(lines.size()) * ImGui::GetTextLineHeightWithSpacing();
}

void wrapped_text(std::string_view text, const ImVec4& colour) {
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    wrapped_text(text);
    ImGui::PopStyleColor();
}

}  // namespace hsr::viz
