// SPDX-License-Identifier: MIT
#include "panels/keys_panel.h"

#include <imgui.h>

#include <algorithm>
#include <utility>

#include "state/strings.h"

namespace hsr::viz {

void keys_panel(const PanelLayout& l) {
    // each key with what it does (the catalogue's [keys], in the student's language)
    static constexpr std::pair<const char*, const char*> rows[] = {
        {"Space", "keys.play"},
        {"→  ←", "keys.step"},
        {"Shift+→  Shift+←", "keys.micro"},
        {"Home  End", "keys.ends"},
        {"PageDown  PageUp", "keys.chapter"},
        {"N  Shift+N", "keys.lesson"},
        {"M", "keys.menu"},
        {"1 … 9", "keys.answer"},
        {"L", "keys.language"},
        {"P", "keys.presets"},
        {"X", "keys.practice"},
        {"R", "keys.report"},
        {"V", "keys.view"},
        {"W", "keys.walk"},
        {"F5", "keys.reload"},
        {"O", "keys.open"},
        {"E", "keys.export"},
        {"Ctrl+Z  Ctrl+Y  S", "keys.edit"},
        {"F1  Esc", "keys.keys"},
        {"[  ]", "keys.column"},
        {"Ctrl+=  Ctrl+−  Ctrl+0", "keys.type_size"},
        {"drag, wheel", "keys.drag"},
        {"Shift+drag, right-click", "keys.draw"},
    };
    // centred on the view, never wider than it (a long translation wraps in its column rather than leave the screen)
    const float view_w = l.width - l.side, view_h = l.height - l.bottom;
    ImGui::SetNextWindowPos(ImVec2(view_w / 2, view_h / 2), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(view_w - 24, 46 * ImGui::GetFontSize()), 0), ImGuiCond_Always);  // 0: fit the height
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(view_w - 24, view_h - 24));
    ImGui::Begin((tr("keys.title") + "###keys").c_str(), nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoResize |
                                                             ImGuiWindowFlags_NoScrollbar);  // its height fits the rows (the wheel still scrolls)
    float key_w = 0;
    for (const auto& [k, what] : rows) key_w = std::max(key_w, ImGui::CalcTextSize(k).x);
    if (ImGui::BeginTable("keys", 2)) {
        ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed, key_w);
        ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
        for (const auto& [k, what] : rows) {
            ImGui::TableNextColumn();
            ImGui::TextColored(ImVec4(0.94f, 0.89f, 0.26f, 1), "%s", k);
            ImGui::TableNextColumn();
            ImGui::TextWrapped("%s", tr(what).c_str());
        }
        ImGui::EndTable();
    }
    ImGui::TextDisabled("hsrviz %s", HSR_VERSION);
    ImGui::End();
}

}  // namespace hsr::viz
