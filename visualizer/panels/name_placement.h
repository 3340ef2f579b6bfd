// SPDX-License-Identifier: MIT
// Where a polygon's name goes in a 2D picture (the raster views' "polygon 2", the depth-sort inset's "#3"): inside
// it and clear of the names placed before it.
#pragma once

#include <algorithm>
#include <initializer_list>
#include <vector>

#include <imgui.h>

namespace hsr::viz {

// The box (x0, y0, x1, y1) of a name of `size` points for the polygon with these screen corners: at their middle, or
// part way towards a corner (each fraction of `towards`), or, with `beside`, next to a polygon too small for it —
// the first that overlaps none of `taken` (else the middle). The box is `pad` points wider each side, and is added
// to `taken`.
inline ImVec4 place_name(const std::vector<ImVec2>& corners, ImVec2 size, float pad, std::initializer_list<float> towards, bool beside,
                         std::vector<ImVec4>& taken) {
    ImVec2 c(0, 0);
    for (const ImVec2& v : corners) c.x += v.x / float(corners.size()), c.y += v.y / float(corners.size());
    std::vector<ImVec2> candidates{c};
    for (const float t : towards)
        for (const ImVec2& v : corners) candidates.push_back(ImVec2(c.x + (v.x - c.x) * t, c.y + (v.y - c.y) * t));
    if (beside)
        for (const float k : {1.1f, 2.2f})
            for (const ImVec2 dir : {ImVec2(0, 1), ImVec2(0, -1), ImVec2(1, 0), ImVec2(-1, 0)})
                candidates.push_back(ImVec2(c.x + dir.x * k * (size.x + 4), c.y + dir.y * k * (size.y + 2)));
    const auto box = [&](ImVec2 at) { return ImVec4(at.x - size.x / 2 - pad, at.y - size.y / 2 - 1, at.x + size.x / 2 + pad, at.y + size.y / 2 + 1); };
    const auto free = [&](const ImVec4& b) {
        return std::none_of(taken.begin(), taken.end(), [&](const ImVec4& t) { return b.x < t.z && t.x < b.z && b.y < t.w && t.y < b.w; });
    };
    ImVec4 b = box(c);
    for (const ImVec2& at : candidates)
        if (free(box(at))) {
            b = box(at);
            break;
        }
    taken.push_back(b);
    return b;
}

}  // namespace hsr::viz
