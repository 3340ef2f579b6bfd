// SPDX-License-Identifier: MIT
// Lines wider than a pixel, as triangles. OpenGL ES 3.0 and WebGL 2 draw GL_LINES one pixel wide whatever glLineWidth
// says (the "bold" edges of a step would look like the faint ones), and a core profile need not draw them wider
// either; so each segment becomes a screen-space rectangle, with square caps so that the corners of an outline meet.
// Pure geometry (no GL): the caller draws the result with an identity transform.
#pragma once

#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "render/colored_vertex.h"

namespace hsr::viz {

// `lines` holds pairs of world-space ends. Each segment is clipped against the near plane (z ≥ −w in clip space:
// an end behind the eye never divides by w ≤ 0), projected, widened to `width` pixels of a viewport `viewport`
// pixels in size, and given as two triangles in normalised device coordinates (x, y, z/w), appended to `out`.
// A segment wholly behind the near plane gives nothing; a segment of no length a square.
void wide_line_triangles(const std::vector<ColoredVertex>& lines, const glm::mat4& view_projection, float width,
                         glm::vec2 viewport, std::vector<ColoredVertex>& out);

}  // namespace hsr::viz
