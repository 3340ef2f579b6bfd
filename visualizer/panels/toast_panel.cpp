// SPDX-License-Identifier: MIT
#include "panels/toast_panel.h"

#include <algorithm>

#include <imgui.h>

#include "panels/wrapped_text.h"

namespace hsr::viz {

void toast_panel(const Toasts& toasts, double now, const PanelLayout& l) {
    const auto notes = toasts.showing(now);
    if (notes.empty()) return;
    const float view_w = l.width - l.side;
    const float width = std::min(view_w - 24, 36 * ImGui::GetFontSize());
    ImGui::SetNextWindowPos(ImVec2(view_w / 2, 12), ImGuiCond_Always, ImVec2(0.5f, 0));
    ImGui::SetNextWindowSize(ImVec2(width, 0));
    const float alpha = float(1 - std::max(0.0, notes.back().faded - 0.75) * 4);  // the last quarter fades
    ImGui::SetNextWindowBgAlpha(0.85f * alpha);
    ImGui::Begin("##notes", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    for (const Toasts::Showing& n : notes) wrapped_text(n.text, ImVec4(1, 1, 1, float(1 - std::max(0.0, n.faded - 0.75) * 4)));
    ImGui::End();
}

}  // namespace hsr::viz
