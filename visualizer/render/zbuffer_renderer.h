// SPDX-License-Identifier: MIT
// Draws a z-buffer lesson in 3D: the scene's polygons, the view frustum, and the frame buffer so far as an image
// standing in the frustum behind the scene, where each fat pixel lines up with what it shows seen from the eye.
#pragma once

#include <vector>

#include "render/label.h"
#include "render/line_batch.h"
#include "scene/scene.h"
#include "state/zbuffer_view.h"

namespace hsr::viz {

void draw_zbuffer_3d(const ZView& view, const algo::Scene& scene, LineBatches& batches, std::vector<Label>& labels);

}  // namespace hsr::viz
