// SPDX-License-Identifier: MIT
#include "panels/keys_panel.h"

#include <imgui.h>

#include <utility>

namespace hsr::viz {

void keys_panel(const PanelLayout& l) {
    static constexpr std::pair<const char*, const char*> rows[] = {
        {"Space", "play / pause"},          {"→  ←", "one Step forward / back"},
        {"Shift+→  Shift+←", "one event (micro-step)"}, {"Home  End", "first / last step"},
        {"PageDown  PageUp", "next / previous chapter"}, {"N  Shift+N", "next / previous lesson"}, {"1 … 9", "answer the open question"},
        {"L", "narration language"},       {"P", "presets: extreme cases, a random scene (0), back (B)"},
        {"X", "practice: exercises the machine grades (1 … 9 or a typed number, Enter: next)"},
        {"R", "error against run time for this algorithm's family"},       {"V", "the other view: 3D, the camera's, the walk-through; in a 2D BSP plan, drive the eye with the arrows"},
        {"F5", "reload the lesson (edits reload by themselves)"}, {"E", "export PNG, trace and scene to hsrviz-export/"},
        {"Ctrl+Z  Ctrl+Y  S", "undo, redo, save an edited 2D scene"}, {"F1  Esc", "show / hide these keys"}, {"[  ]", "panel column narrower / wider (remembered)"},
        {"Ctrl+=  Ctrl+−  Ctrl+0", "larger / smaller type and panels, back to the start"},
        {"drag, wheel", "orbit and zoom the 3D view; drag an eye or a segment's end in 2D"},
        {"Shift+drag, right-click", "2D scenes: a new segment; z-buffer pixels: a new triangle; delete what is clicked"},
    };
    ImGui::SetNextWindowPos(ImVec2((l.width - l.side) / 2, (l.height - l.bottom) / 2), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::Begin("Keys", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
    if (ImGui::BeginTable("keys", 2)) {
        for (const auto& [k, what] : rows) {
            ImGui::TableNextColumn();
            ImGui::TextColored(ImVec4(0.94f, 0.89f, 0.26f, 1), "%s", k);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(what);
        }
        ImGui::EndTable();
    }
    ImGui::TextDisabled("hsrviz %s", HSR_VERSION);
    ImGui::End();
}

}  // namespace hsr::viz
