// SPDX-License-Identifier: MIT
#include "panels/work_panel.h"

#include <algorithm>
#include <cmath>

#include "panels/panel_style.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {

void work_panel(const algo::WorkProgress& p, float width, float height) {
    const float box = std::min(width - 24, 36 * ImGui::GetFontSize());
    ImGui::SetNextWindowPos(ImVec2(width / 2, height / 2), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(box, 0));
    ImGui::Begin((tr("work.title") + "###work").c_str(), nullptr, fixed | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs);
    wrapped_text(p.sentence());
    // The bar: its share when the total is known, else a block sweeping to and fro (the window is alive)
    const float bar_w = ImGui::GetContentRegionAvail().x, bar_h = ImGui::GetFrameHeight();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(at, ImVec2(at.x + bar_w, at.y + bar_h), ImGui::GetColorU32(bit_clear));
    if (p.total > 0) {
        const float share = float(std::clamp(p.done / p.total, 0.0, 1.0));
        draw->AddRectFilled(at, ImVec2(at.x + share * bar_w, at.y + bar_h), ImGui::GetColorU32(highlight_bg));
    } else {
        const float block = bar_w / 5, sweep = float(0.5 - 0.5 * std::cos(p.seconds * 2.0));
        const float x = at.x + sweep * (bar_w - block);
        draw->AddRectFilled(ImVec2(x, at.y), ImVec2(x + block, at.y + bar_h), ImGui::GetColorU32(highlight_bg));
    }
    ImGui::Dummy(ImVec2(bar_w, bar_h));
    wrapped_text(tr("work.stop"), dim_text);
    ImGui::End();
}

}  // namespace hsr::viz
