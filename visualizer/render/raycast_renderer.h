// SPDX-License-Identifier: MIT
// Draws a ray-casting view in 3D: the scene's polygons, the view frustum, the grid's cells the current ray has
// walked (the last one bright), the ray up to its nearest hit, and that hit.
#pragma once

#include <vector>

#include "render/label.h"
#include "render/line_batch.h"
#include "scene/scene.h"
#include "state/raycast_view.h"

namespace hsr::viz {

void draw_raycast_view(const RayView& view, const algo::Scene& scene, LineBatches& batches, std::vector<Label>& labels);

}  // namespace hsr::viz
