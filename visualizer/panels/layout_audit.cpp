// SPDX-License-Identifier: MIT
#include "panels/layout_audit.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>
#include <imgui_internal.h>

namespace hsr::viz {
namespace {

void note(const char* what, float by) {
    char text[256];
    std::snprintf(text, sizeof text, "box \"%s\" %s by %.0f px", ImGui::GetCurrentWindow()->Name, what, by);
    auto& all = layout_problems();
    if (std::find(all.begin(), all.end(), text) == all.end()) all.emplace_back(text);
}

}  // namespace

std::vector<std::string>& layout_problems() {
    static std::vector<std::string> problems;
    return problems;
}

void audit_current_window() {
    const ImGuiWindow* w = ImGui::GetCurrentWindow();
    const float right = w->DC.CursorMaxPos.x - w->InnerClipRect.Max.x;
    const float below = w->DC.CursorMaxPos.y - w->InnerClipRect.Max.y;
    if (right > 1 && !w->ScrollbarX) note("cut on the right", right);
    if (below > 1 && !w->ScrollbarY) note("cut at the bottom", below);
    if (w->ScrollbarY && w->ScrollMax.y > 1) {  // reachable, but the class sees only a part: counted, not an error
        auto& boxes = scrolling_boxes();
        const std::string name = std::string(w->Name).substr(0, std::string(w->Name).find("###"));
        if (std::find(boxes.begin(), boxes.end(), name) == boxes.end()) boxes.push_back(name);
    }
}

std::vector<std::string>& scrolling_boxes() {
    static std::vector<std::string> boxes;
    return boxes;
}

bool& result_scrolls() {
    static bool scrolls = false;
    return scrolls;
}

void note_broken_word() { note("breaks a word too wide for its line, width", ImGui::GetContentRegionAvail().x); }

}  // namespace hsr::viz
