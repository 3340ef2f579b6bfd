// SPDX-License-Identifier: MIT
// An independent reference for antialiasing and transparency: each pixel sampled by s × s rays cast in world space
// (no rasterising, no snapping), every polygon a ray meets found by its plane and an inside test, the hits sorted by
// distance and composited front to back. The pixel is the mean of its rays, premultiplied over nothing.
#pragma once

#include <vector>

#include <glm/vec4.hpp>

#include "raster/screen_polygon.h"
#include "scene/scene.h"

namespace hsr::analysis {

glm::dvec4 supersampled_pixel(const algo::Scene& scene, algo::Viewport viewport, int x, int y, int rays_per_side);
std::vector<glm::dvec4> supersampled_image(const algo::Scene& scene, algo::Viewport viewport, int rays_per_side);

}  // namespace hsr::analysis
