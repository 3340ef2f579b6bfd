// SPDX-License-Identifier: MIT
// Draws Roberts' line drawing from the scene's eye: each finished edge solid where it shows and faint dashes where a
// body hides it, back edges faint, the edge under test bold with the parts found hidden so far, and the body it is
// tested against outlined.
#pragma once

#include <vector>

#include <glm/mat4x4.hpp>

#include "render/label.h"
#include "render/line_batch.h"
#include "scene/scene.h"
#include "state/roberts_session.h"

namespace hsr::viz {

void draw_roberts_view(const RobertsView& view, const algo::Scene& scene, LineBatches& batches, std::vector<Label>& labels);
// The scene's own camera at the view's aspect: a line drawing is what one eye sees.
glm::mat4 roberts_camera(const algo::Scene& scene, float aspect);

}  // namespace hsr::viz
