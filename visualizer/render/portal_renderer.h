// SPDX-License-Identifier: MIT
// The 3D walk-through of a portal_render lesson: the rooms, the polygons drawn solid in their cell's colour and
// those culled as faint outlines, the openings outlined, the eye, and the narrowed frusta as rays from the eye
// through the corners of each opening's visible part.
#pragma once

#include <vector>

#include "render/label.h"
#include "render/line_batch.h"
#include "state/portal_session.h"

namespace hsr::viz {

void draw_portal_view(const PortalView& view, LineBatches& batches, std::vector<Label>& labels);
// The centre and radius of the floor plan's rooms, for the orbit camera.
void portal_view_bounds(const algo::CellModel& model, glm::vec3& centre, float& radius);

}  // namespace hsr::viz
