// SPDX-License-Identifier: MIT
// Draws a depth-sort lesson in the canonical view volume (the viewpoint far away along −z): the polygons still to
// draw faint, those drawn solid, the pair under examination bold (R yellow, Q blue), and for tests 3 and 4 the
// plane they test against.
#pragma once

#include <vector>

#include "render/label.h"
#include "render/line_batch.h"
#include "state/depth_sort_session.h"

namespace hsr::viz {

void draw_depth_sort_view(const DepthSortView& view, LineBatches& batches, std::vector<Label>& labels);

}  // namespace hsr::viz
