// SPDX-License-Identifier: MIT
#include "render/wide_lines.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace hsr::viz {

void wide_line_triangles(const std::vector<ColoredVertex>& lines, const glm::mat4& view_projection, float width,
                         glm::vec2 viewport, std::vector<ColoredVertex>& out) {
    if (!(viewport.x > 0 && viewport.y > 0)) return;
    const glm::vec2 to_ndc = 2.0f / viewport;  // one pixel in normalised device coordinates
    for (std::size_t k = 0; k + 1 < lines.size(); k += 2) {
        glm::vec4 a = view_projection * glm::vec4(lines[k].position, 1), b = view_projection * glm::vec4(lines[k + 1].position, 1);
        // the near plane: inside where z + w ≥ 0; clip space is linear along the segment, so the crossing is found there
        const float da = a.z + a.w, db = b.z + b.w;
        if (!(da >= 0 || db >= 0)) continue;  // wholly behind (or not a number)
        if (da < 0) a += (b - a) * (da / (da - db));
        if (db < 0) b += (a - b) * (db / (db - da));
        if (!(a.w > 0 && b.w > 0)) continue;  // on the eye itself: no direction to draw
        const glm::vec3 pa = glm::vec3(a) / a.w, pb = glm::vec3(b) / b.w;
        // along and across the segment, in pixels
        glm::vec2 along = (glm::vec2(pb) - glm::vec2(pa)) / to_ndc;
        const float length = glm::length(along);
        along = length > 1e-6f ? along / length : glm::vec2(1, 0);
        const glm::vec2 half_along = along * (0.5f * width) * to_ndc, half_across = glm::vec2(-along.y, along.x) * (0.5f * width) * to_ndc;
        const glm::vec4 color = lines[k].color;
        const auto corner = [&](const glm::vec3& p, glm::vec2 offset) { return ColoredVertex{{glm::vec2(p) + offset, p.z}, color}; };
        const ColoredVertex a1 = corner(pa, -half_along + half_across), a2 = corner(pa, -half_along - half_across);
        const ColoredVertex b1 = corner(pb, half_along + half_across), b2 = corner(pb, half_along - half_across);
        out.insert(out.end(), {a1, a2, b1, b1, a2, b2});
    }
}

}  // namespace hsr::viz
