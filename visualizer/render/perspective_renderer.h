// SPDX-License-Identifier: MIT
// Draws the perspective transform's picture at the warp the view has reached: the canonical box faint (where the
// volume goes), the view volume's edges, the eye while it has a place, each point with its projector, the pair under
// comparison bold, and each occluding pair found joined.
#pragma once

#include <vector>

#include "render/label.h"
#include "render/line_batch.h"
#include "scene/scene.h"
#include "state/perspective_session.h"

namespace hsr::viz {

void draw_perspective_view(const PerspectiveView& view, const algo::Scene& scene, LineBatches& batches, std::vector<Label>& labels);

}  // namespace hsr::viz
