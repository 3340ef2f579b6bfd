// SPDX-License-Identifier: MIT
#include "panels/raycast_panels.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "panels/panel_style.h"
#include "panels/wrapped_text.h"

namespace hsr::viz {

void raycast_image(const RayCastSession& s, float x, float y, float w, float h) {
    const RayView& v = s.view();
    const float cell = std::clamp(std::min(w * 0.35f / float(v.viewport.width), h * 0.35f / float(v.viewport.height)), 3.0f, 16.0f);
    const float iw = cell * float(v.viewport.width), ih = cell * float(v.viewport.height);
    place(x + 12, y + h - ih - 40, iw + 16, ih + 36);
    ImGui::Begin("Image", nullptr, fixed | ImGuiWindowFlags_NoScrollbar);
    ImDrawList* d = ImGui::GetWindowDrawList();
    const ImVec2 o = ImGui::GetCursorScreenPos();
    const auto& polygons = s.scene().polygons;
    for (int py = 0; py < v.viewport.height; ++py)
        for (int px = 0; px < v.viewport.width; ++px) {
            const std::int32_t k = v.owner[std::size_t(py) * std::size_t(v.viewport.width) + std::size_t(px)];
            const bool cast = py < v.ray_y || (py == v.ray_y && px < v.ray_x) || v.done;
            ImU32 c = cast ? IM_COL32(40, 43, 50, 255) : IM_COL32(24, 26, 30, 255);
            if (k >= 0) {
                const algo::Color& col = polygons[std::size_t(k)].color;
                c = IM_COL32(col.r, col.g, col.b, 255);
            }
            d->AddRectFilled(ImVec2(o.x + float(px) * cell, o.y + float(py) * cell),
                             ImVec2(o.x + float(px + 1) * cell - 1, o.y + float(py + 1) * cell - 1), c);
        }
    if (v.ray_x >= 0)
        d->AddRect(ImVec2(o.x + float(v.ray_x) * cell - 1, o.y + float(v.ray_y) * cell - 1),
                   ImVec2(o.x + float(v.ray_x + 1) * cell + 1, o.y + float(v.ray_y + 1) * cell + 1), IM_COL32(255, 230, 90, 255), 0, 0, canvas_px(2));
    ImGui::Dummy(ImVec2(iw, ih));
    ImGui::End();
}

void raycast_state_panel(const RayCastSession& s, const PanelLayout& l) {
    begin_column_box(l, Box::state, "Ray");
    const RayView& v = s.view();
    wrapped_text(std::string(algo::to_string(v.acceleration)) + " · " + std::to_string(v.viewport.width) + "×" +
                     std::to_string(v.viewport.height) + " rays · t = 0 on the near plane, 1 on the far plane",
                 dim_text);
    if (v.ray_x >= 0) {
        ImGui::Text("pixel (%d, %d): %u tests so far", v.ray_x, v.ray_y, v.ray_tests);
        if (v.acceleration == algo::Acceleration::grid && !v.cells.empty())
            ImGui::Text("%zu cells walked, now in [%d, %d, %d] of %d×%d×%d", v.cells.size(), v.cells.back().x,
                        v.cells.back().y, v.cells.back().z, v.grid->cells.x, v.grid->cells.y, v.grid->cells.z);
        if (v.acceleration == algo::Acceleration::octree) ImGui::Text("%d octree nodes entered", v.nodes);
        if (v.tested >= 0)
            ImGui::Text("tested polygon %d: %s", s.scene().polygons[std::size_t(v.tested)].id,
                        v.tested_hit ? ("hit at t = " + std::to_string(v.tested_t)).c_str() : "missed");
        if (v.nearest >= 0)
            ImGui::TextColored(ImVec4(0.9f, 0.62f, 0, 1), "nearest: polygon %d at t = %.5g", s.scene().polygons[std::size_t(v.nearest)].id, v.nearest_t);
        else
            ImGui::TextColored(dim_text, "nearest: none yet");
    }
    char totals[160];
    std::snprintf(totals, sizeof totals, "%llu rays · %llu primitive tests (%.3g per ray)", (unsigned long long)v.rays,
                  (unsigned long long)v.tests, v.rays ? double(v.tests) / double(v.rays) : 0.0);
    wrapped_text(totals, dim_text);
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
