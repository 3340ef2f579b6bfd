#include "panels/zmerge_panels.h"

#include <algorithm>

#include <imgui.h>

#include "panels/fat_pixels.h"
#include "panels/panel_style.h"

namespace hsr::viz {

void zmerge_canvas(const ZMergeSession& s, float x, float y, float w, float h) {
    const ZMergeView& v = s.view();
    ImDrawList* d = begin_canvas("##zmerge canvas", x, y, w, h);
    const float margin = 20;
    const float cell = std::max(2.0f, std::min((w - 4 * margin) / (3.0f * float(v.viewport.width)), (h - 2 * margin - 40) / float(v.viewport.height)));
    const float step = cell * float(v.viewport.width) + margin;
    const auto colour = [&](std::int32_t k) { return k >= 0 ? rgb((*v.polygons)[std::size_t(k)].color) : rgb({40, 43, 50}); };
    const auto at = [&](int px, int py) { return std::size_t(py) * std::size_t(v.viewport.width) + std::size_t(px); };
    const char* titles[3] = {"part A (first half)", "part B (the rest)", "merged: the nearer of A and B"};
    for (int panel = 0; panel < 3; ++panel) {
        const ImVec2 o(x + margin + float(panel) * step, y + margin + 24);
        d->AddText(ImVec2(o.x, y + margin), IM_COL32(220, 220, 220, 255), titles[panel]);
        pixel_grid(d, o, cell, v.viewport, [&](int px, int py) {
            const std::size_t k = at(px, py);
            if (panel == 0) return colour(v.a->polygon[k]);
            if (panel == 1) return colour(v.b->polygon[k] < 0 ? -1 : v.b->polygon[k] + std::int32_t(v.b_offset));
            return v.merged[k] == -2 ? rgb({24, 26, 30}) : colour(v.merged[k]);
        });
        if (v.x >= 0) {
            const bool chosen = panel == 2 || (panel == 0) == v.from_a;
            d->AddRect(ImVec2(o.x + float(v.x) * cell - 2, o.y + float(v.y) * cell - 2),
                       ImVec2(o.x + float(v.x + 1) * cell + 1, o.y + float(v.y + 1) * cell + 1),
                       chosen ? IM_COL32(90, 220, 130, 255) : IM_COL32(240, 80, 60, 255), 0, 0, 3);
        }
    }
    ImGui::End();
}

void zmerge_state_panel(const ZMergeSession& s, const PanelLayout& l) {
    begin_column_box(l, Box::state, "Merge");
    const ZMergeView& v = s.view();
    ImGui::TextColored(dim_text, "%s · smaller codes are nearer · on a tie B stays",
                       std::string(algo::to_string(s.lesson().depth_format)).c_str());
    if (v.x >= 0)
        ImGui::Text("pixel (%d, %d): Za = %u, Zb = %u → %s", v.x, v.y, v.depth_a, v.depth_b, v.from_a ? "A" : "B");
    ImGui::Text("%llu pixels from A · %llu from B", (unsigned long long)v.from_a_count, (unsigned long long)v.from_b_count);
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
