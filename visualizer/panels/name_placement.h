// SPDX-License-Identifier: MIT
// Where a polygon's name goes in a 2D picture (the raster views' "polygon 2", the depth-sort inset's "#3"): inside
// it and clear of the names placed before it.
#pragma once

#include <algorithm>
#include <initializer_list>
#include <limits>
#include <vector>

#include <imgui.h>

namespace hsr::viz {

// Whether two boxes (x0, y0, x1, y1) overlap.
inline bool boxes_overlap(const ImVec4& a, const ImVec4& b) { return a.x < b.z && b.x < a.z && a.y < b.w && b.y < a.w; }

// The box (x0, y0, x1, y1) of a name of `size` points for the polygon with these screen corners: at their middle, or
// part way towards a corner (each fraction of `towards`), or, with `beside`, next to a polygon too small for it —
// the first that overlaps none of `taken` and, given `within`, lies inside it (else the one that covers least of
// `taken`). The box is `pad` points wider each side, and is added to `taken`.
inline ImVec4 place_name(const std::vector<ImVec2>& corners, ImVec2 size, float pad, std::initializer_list<float> towards, bool beside,
                         std::vector<ImVec4>& taken, const ImVec4* within = nullptr) {
    ImVec2 c(0, 0);
    for (const ImVec2& v : corners) c.x += v.x / float(corners.size()), c.y += v.y / float(corners.size());
    std::vector<ImVec2> candidates{c};
    for (const float t : towards)
        for (const ImVec2& v : corners) candidates.push_back(ImVec2(c.x + (v.x - c.x) * t, c.y + (v.y - c.y) * t));
    // the same slid sideways by a quarter and a half of the name: a long name in a thin polygon clears its edges so
    const std::size_t inner = candidates.size();
    for (const float slide : {0.25f, -0.25f, 0.5f, -0.5f})
        for (std::size_t i = 0; i < inner; ++i) candidates.push_back(ImVec2(candidates[i].x + slide * size.x, candidates[i].y));
    if (beside)
        for (const float k : {1.1f, 2.2f})
            for (const ImVec2 dir : {ImVec2(0, 1), ImVec2(0, -1), ImVec2(1, 0), ImVec2(-1, 0)})
                candidates.push_back(ImVec2(c.x + dir.x * k * (size.x + 4), c.y + dir.y * k * (size.y + 2)));
    const auto box = [&](ImVec2 at) { return ImVec4(at.x - size.x / 2 - pad, at.y - size.y / 2 - 1, at.x + size.x / 2 + pad, at.y + size.y / 2 + 1); };
    const auto inside = [&](const ImVec4& b) { return !within || (b.x >= within->x && b.y >= within->y && b.z <= within->z && b.w <= within->w); };
    const auto overlap = [&](const ImVec4& b) {  // the area of `taken` the box would cover
        float sum = 0;
        for (const ImVec4& t : taken) sum += std::max(0.0f, std::min(b.z, t.z) - std::max(b.x, t.x)) * std::max(0.0f, std::min(b.w, t.w) - std::max(b.y, t.y));
        return sum;
    };
    // the first candidate clear of everything; where none is, the one covering least (the middle if none fits `within`)
    ImVec4 b = box(c);
    float least = inside(b) ? overlap(b) : std::numeric_limits<float>::infinity();
    for (const ImVec2& at : candidates) {
        if (!inside(box(at))) continue;
        const float covered = overlap(box(at));
        if (covered < least) least = covered, b = box(at);
        if (covered == 0) break;
    }
    taken.push_back(b);
    return b;
}

}  // namespace hsr::viz
