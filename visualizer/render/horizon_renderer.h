// SPDX-License-Identifier: MIT
// The floating horizon's terrain in 3D, beside its screen: the curves already drawn in their colours where they
// showed and faint where hidden, the curves still to come faint, the section under the column being tested, and a
// camera of its own that looks the way the lesson's view does, a little from the side, framed into the view's right.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "render/label.h"
#include "render/line_batch.h"
#include "state/horizon_session.h"

namespace hsr::viz {

// The part of the view's width the screen canvas takes, from the left; the terrain is drawn in the rest.
inline constexpr float horizon_canvas_share = 0.6f;

// The terrain's camera, framed into the view's right part (view_w × view_h, the whole 3D view); nothing for a terrain
// too tall to draw (heights beyond 10^6 times its size: the extreme cases).
std::optional<glm::mat4> horizon_terrain_camera(const HorizonView& v, float view_w, float view_h);
// `nearest` and `farthest` label the first and the last curve (in the student's language).
void draw_horizon_terrain(const HorizonView& v, LineBatches& batches, std::vector<Label>& labels, const std::string& nearest,
                          const std::string& farthest);

}  // namespace hsr::viz
