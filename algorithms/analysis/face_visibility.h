// SPDX-License-Identifier: MIT
// The reference back-face culling is checked against: how many pixels of the camera's image each face wins in a
// ray cast of all the faces, both sides, nothing culled. On a closed opaque solid seen from outside a culled face
// wins none; a non-convex solid has kept faces that win none too (culling is not enough: the hidden-surface
// algorithm must still run), and an open surface has culled faces that win pixels (culling is wrong there).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "culling/backface.h"
#include "raster/screen_polygon.h"

namespace hsr::analysis {

// One count per face, in the faces' order. Faces are polygons of 3 or more vertices (faces_of gives them).
std::vector<std::size_t> pixels_seen(std::span<const algo::Face> faces, const algo::Camera& camera, algo::Viewport size);

}  // namespace hsr::analysis
