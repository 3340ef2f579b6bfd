// SPDX-License-Identifier: MIT
#include "panels/zmerge_panels.h"

#include <algorithm>

#include <imgui.h>

#include "panels/fat_pixels.h"
#include "panels/panel_style.h"
#include "panels/state_legend.h"
#include "panels/wrapped_text.h"
#include "state/strings.h"

namespace hsr::viz {

namespace {

// A depth code as a grey: the nearest code drawn in either part white, the farthest a dark grey; a pixel no
// polygon covers (its code the cleared far code) the background's colour.
struct DepthShade {
    std::uint32_t lo = ~0u, hi = 0;
    bool smaller_is_nearer = true;
    ImU32 operator()(std::uint32_t code, bool covered) const {
        if (!covered) return rgb({40, 43, 50});
        float t = hi > lo ? float(code - lo) / float(hi - lo) : 0.0f;
        if (smaller_is_nearer) t = 1 - t;
        const auto g = std::uint8_t(70 + 185 * std::clamp(t, 0.0f, 1.0f));
        return rgb({g, g, g});
    }
    std::uint32_t nearer(std::uint32_t a, std::uint32_t b) const { return smaller_is_nearer ? std::min(a, b) : std::max(a, b); }
};

}  // namespace

// Six fat-pixel panels: A, B and the merge, each as its colours and as its depth buffer. Laid out 3 × 2 or 2 × 3,
// whichever gives the larger pixels in this view.
void zmerge_canvas(const ZMergeSession& s, float x, float y, float w, float h) {
    const ZMergeView& v = s.view();
    ImDrawList* d = begin_canvas("##zmerge canvas", x, y, w, h);
    // room for the row numbers left of each grid (two digits on a projector), and for the frames' legend below
    const float margin = std::max(20.0f, grid_number_room(v.viewport) + 6), title = ImGui::GetTextLineHeightWithSpacing() + 4;
    const float W = float(v.viewport.width), H = float(v.viewport.height), legend = legend_height();
    const auto cell_for = [&](float columns, float rows) {
        return std::min((w - (columns + 1) * margin) / (columns * W), (h - legend - (rows + 1) * margin - rows * title) / (rows * H));
    };
    const bool wide = cell_for(3, 2) >= cell_for(2, 3);  // columns A, B, merged; rows colour, depth (or transposed)
    const float cell = std::max(2.0f, wide ? cell_for(3, 2) : cell_for(2, 3));
    const auto colour = [&](std::int32_t k) { return k >= 0 ? rgb((*v.polygons)[std::size_t(k)].color) : rgb({40, 43, 50}); };
    const auto at = [&](int px, int py) { return std::size_t(py) * std::size_t(v.viewport.width) + std::size_t(px); };
    DepthShade shade{.smaller_is_nearer = algo::smaller_is_nearer(s.lesson().depth_format)};
    for (const auto* part : {v.a.get(), v.b.get()})
        for (std::size_t k = 0; k < part->depth.size(); ++k)
            if (part->polygon[k] >= 0) shade.lo = std::min(shade.lo, part->depth[k]), shade.hi = std::max(shade.hi, part->depth[k]);
    const std::string titles[3][2] = {{tr("zmerge.a_colours"), tr("zmerge.a_depth")},
                                      {tr("zmerge.b_colours"), tr("zmerge.b_depth")},
                                      {tr("zmerge.merged_colours"), tr("zmerge.merged_depth")}};
    for (int part = 0; part < 3; ++part)
        for (int kind = 0; kind < 2; ++kind) {
            const int column = wide ? part : kind, row = wide ? kind : part;
            const ImVec2 o(x + margin + float(column) * (cell * W + margin), y + margin + title + float(row) * (cell * H + margin + title));
            d->AddText(ImVec2(o.x, o.y - title), IM_COL32(220, 220, 220, 255), titles[part][kind].c_str());
            pixel_grid(d, o, cell, v.viewport, [&](int px, int py) {
                const std::size_t k = at(px, py);
                const bool unmerged = v.merged[k] == -2;
                if (kind == 0) {
                    if (part == 0) return colour(v.a->polygon[k]);
                    if (part == 1) return colour(v.b->polygon[k] < 0 ? -1 : v.b->polygon[k] + std::int32_t(v.b_offset));
                    return unmerged ? rgb({24, 26, 30}) : colour(v.merged[k]);
                }
                if (part == 0) return shade(v.a->depth[k], v.a->polygon[k] >= 0);
                if (part == 1) return shade(v.b->depth[k], v.b->polygon[k] >= 0);
                return unmerged ? rgb({24, 26, 30}) : shade(shade.nearer(v.a->depth[k], v.b->depth[k]), v.merged[k] >= 0);
            });
            grid_numbers(d, o, cell, v.viewport);
            if (v.x >= 0) {  // the pixel merged last: green where its value came from, red where it lost
                const bool chosen = part == 2 || (part == 0) == v.from_a;
                d->AddRect(ImVec2(o.x + float(v.x) * cell - 2, o.y + float(v.y) * cell - 2),
                           ImVec2(o.x + float(v.x + 1) * cell + 1, o.y + float(v.y + 1) * cell + 1),
                           ImGui::GetColorU32(chosen ? colour_of(zmerge_colours::nearer) : colour_of(zmerge_colours::farther)), 0, 0, canvas_px(3));
            }
        }
    if (v.x >= 0) canvas_legend(d, x + margin, y + h - 4, zmerge_colours::all);  // what the frames' colours say
    ImGui::End();
}

void zmerge_state_panel(const ZMergeSession& s, const PanelLayout& l) {
    begin_column_box(l, Box::state, (tr("zmerge.title") + "###state").c_str());
    const ZMergeView& v = s.view();
    const auto n = [](auto value) { return std::to_string(value); };
    wrapped_text(tr("zmerge.rule", {{"format", window_strings().name(algo::to_string(s.lesson().depth_format))}}), dim_text);
    if (v.x >= 0)
        wrapped_text(tr("zmerge.pixel", {{"x", n(v.x)}, {"y", n(v.y)}, {"za", n(v.depth_a)}, {"zb", n(v.depth_b)}, {"from", v.from_a ? "A" : "B"}}));
    wrapped_text(tr("zmerge.counts", {{"a", n(v.from_a_count)}, {"b", n(v.from_b_count)}, {"background", n(v.background_count)}}));
    end_column_box(l, Box::state);
}

}  // namespace hsr::viz
