// SPDX-License-Identifier: MIT
// Draws the intersection test: the scene's polygons faint, the rays (the one under test bold), the volumes of the
// nodes the ray has reached coloured by what they were (met, missed, a false alarm), the node at work in yellow, the
// primitive under test and the hit that answered the ray.
#pragma once

#include <vector>

#include "render/label.h"
#include "render/line_batch.h"
#include "scene/scene.h"
#include "state/intersection_session.h"

namespace hsr::viz {

void draw_intersection_view(const IntersectionView& view, const algo::Scene& scene, LineBatches& batches, std::vector<Label>& labels);
// Where the scene sits, for the orbit camera: the root's box and the rays' origins.
void intersection_view_bounds(const IntersectionView& view, glm::vec3& centre, float& radius);

}  // namespace hsr::viz
