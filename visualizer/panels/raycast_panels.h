// SPDX-License-Identifier: MIT
// The panels of a ray-casting lesson: the image filled ray by ray (fat pixels, over the 3D view's corner) and the
// current ray's numbers.
#pragma once

#include "panels/lesson_panels.h"
#include "state/raycast_session.h"

namespace hsr::viz {

// The image, in the bottom-left corner of the view area (x, y, w, h in window points).
void raycast_image(const RayCastSession& s, float x, float y, float w, float h);
void raycast_state_panel(const RayCastSession& s, const PanelLayout& layout);

}  // namespace hsr::viz
