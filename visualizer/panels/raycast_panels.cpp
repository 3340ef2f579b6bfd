// SPDX-License-Identifier: MIT
#include "panels/raycast_panels.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "panels/panel_style.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {

void raycast_image(const RayCastSession& s, float x, float y, float w, float h) {
    const RayView& v = s.view();
    const float cell = std::clamp(std::min(w * 0.35f / float(v.viewport.width), h * 0.35f / float(v.viewport.height)), 3.0f, 16.0f);
    const float iw = cell * float(v.viewport.width), ih = cell * float(v.viewport.height);
    place(x + 12, y + h - ih - 40, iw + 16, ih + 36);
    ImGui::Begin((tr("raycast.image") + "###image").c_str(), nullptr, fixed | ImGuiWindowFlags_NoScrollbar);
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
    begin_column_box(l, Box::state, (tr("raycast.title") + "###state").c_str());
    const RayView& v = s.view();
    const auto n = [](auto value) { return std::to_string(value); };
    wrapped_text(tr("raycast.detail", {{"acceleration", window_strings().say(algo::term(v.acceleration))},
                                       {"width", n(v.viewport.width)}, {"height", n(v.viewport.height)}}),
                 dim_text);
    if (v.examined >= 0 && std::size_t(v.examined) < v.octree.size()) {  // BuildOctree, at this cell
        const OctreeCellView& c = v.octree[std::size_t(v.examined)];
        const algo::Vec3 size = c.hi - c.lo;
        wrapped_text(tr("raycast.octree_cell", {{"node", n(v.examined)}, {"depth", n(c.depth)},
                                                {"edge", algo::format_number(std::max({size.x, size.y, size.z}))},
                                                {"primitives", n(c.primitives)}, {"limit", n(s.octree_options().max_per_leaf)},
                                                {"voxel", algo::format_number(s.octree_voxel())}}));
        if (c.leaf)  // in the colours of the 3D view's leaves: green for few primitives, amber for a voxel
            wrapped_text(tr("raycast.octree_leaf", {{"reason", window_strings().say(algo::term(c.reason))}}),
                         c.reason == algo::OctreeStop::voxel_size ? ImVec4(0.9f, 0.62f, 0.0f, 1) : ImVec4(0.35f, 0.8f, 0.55f, 1));
        if (c.split) wrapped_text(tr("raycast.octree_split"), ImVec4(0.34f, 0.71f, 0.91f, 1));
    }
    if (v.ray_x >= 0) {
        wrapped_text(tr("raycast.pixel", {{"x", n(v.ray_x)}, {"y", n(v.ray_y)}, {"tests", n(v.ray_tests)}}));
        if (v.acceleration == algo::Acceleration::grid && !v.cells.empty())
            wrapped_text(tr("raycast.cells", {{"walked", n(v.cells.size())}, {"i", n(v.cells.back().x)}, {"j", n(v.cells.back().y)},
                                              {"k", n(v.cells.back().z)}, {"nx", n(v.grid->cells.x)}, {"ny", n(v.grid->cells.y)},
                                              {"nz", n(v.grid->cells.z)}}));
        if (v.acceleration == algo::Acceleration::octree) wrapped_text(tr("raycast.nodes", {{"nodes", n(v.nodes)}}));
        if (v.acceleration == algo::Acceleration::bvh) wrapped_text(tr("raycast.bvh_nodes", {{"nodes", n(v.nodes)}}));
        if (v.tested >= 0)
            wrapped_text(tr(v.tested_hit ? "raycast.tested_hit" : "raycast.tested_missed",
                            {{"polygon", n(s.scene().polygons[std::size_t(v.tested)].id)}, {"t", algo::format_number(v.tested_t)}}));
        if (v.nearest >= 0)
            wrapped_text(tr("raycast.nearest", {{"polygon", n(s.scene().polygons[std::size_t(v.nearest)].id)}, {"t", algo::format_number(v.nearest_t)}}),
                         ImVec4(0.9f, 0.62f, 0, 1));
        else
            wrapped_text(tr("raycast.nearest_none"), dim_text);
    }
    if (v.examined >= 0) {  // no ray yet while the octree is built
        end_column_box(l, Box::state);
        return;
    }
    char per_ray[32];
    std::snprintf(per_ray, sizeof per_ray, "%.3g", v.rays ? double(v.tests) / double(v.rays) : 0.0);
    wrapped_text(tr("raycast.totals", {{"rays", n(v.rays)}, {"tests", n(v.tests)}, {"per_ray", per_ray}}), dim_text);
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
