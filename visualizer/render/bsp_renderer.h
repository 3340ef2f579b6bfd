// SPDX-License-Identifier: MIT
// Draws a BSP view in world space: the polygons (faint until painted, then opaque with their painter's number),
// the current node's splitting plane as a translucent quad, the eye, and for a 2D scene (segments in z = 0) every
// splitting line clipped to the region of its node, the classroom picture. Reads the view; changes nothing.
#pragma once

#include <vector>

#include "render/label.h"
#include "render/line_batch.h"
#include "scene/scene.h"
#include "state/bsp_view.h"

namespace hsr::viz {

void draw_bsp_view(const BspView& view, const algo::Scene& scene, LineBatches& batches, std::vector<Label>& labels);
void bsp_view_bounds(const BspView& view, glm::vec3& centre, float& radius);
// What the view draws, to frame it: the polygons' corners and the eye.
std::vector<glm::vec3> bsp_view_points(const BspView& view);

}  // namespace hsr::viz
