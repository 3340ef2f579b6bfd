// SPDX-License-Identifier: MIT
#include "panels/preset_panel.h"

#include <imgui.h>

#include "state/strings.h"

namespace hsr::viz {

void preset_panel(const std::vector<Preset>& presets, bool has_random, std::uint32_t next_seed, bool away_from_lesson,
                  const PanelLayout& l, UiActions& out) {
    ImGui::SetNextWindowPos(ImVec2((l.width - l.side) / 2, (l.height - l.bottom) / 2), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(420, 0), ImVec2(l.width - l.side - 40, l.height - l.bottom - 40));
    ImGui::Begin((tr("presets.title") + "###presets").c_str(), nullptr,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
    if (presets.empty()) ImGui::TextDisabled("%s", tr("presets.none").c_str());
    for (std::size_t k = 0; k < presets.size(); ++k) {
        ImGui::PushID(int(k));
        const std::string label = (k < 9 ? std::to_string(k + 1) + "  " : "   ") + presets[k].name;
        if (ImGui::Button(label.c_str())) out.preset = int(k);
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 520);
        ImGui::TextDisabled("%s", presets[k].promise.c_str());
        ImGui::PopTextWrapPos();
        ImGui::PopID();
    }
    ImGui::Separator();
    if (has_random) {
        const std::string label = "0  " + tr("presets.random", {{"seed", std::to_string(next_seed)}}) + "###random";
        if (ImGui::Button(label.c_str())) out.random_scene = true;
    }
    if (away_from_lesson && ImGui::Button(("B  " + tr("presets.back") + "###back").c_str())) out.back_to_lesson = true;
    ImGui::TextDisabled("%s", tr("presets.how").c_str());
    ImGui::End();
}

}  // namespace hsr::viz
