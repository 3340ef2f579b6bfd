// SPDX-License-Identifier: MIT
// The perspective transform's state box: where the warp is, each point before and after the divide by w, the pair
// under comparison with its numbers both ways, and what each way divides.
#pragma once

#include "panels/lesson_panels.h"
#include "state/perspective_session.h"

namespace hsr::viz {

// The state box; the points' table is in it unless `table_in_view` (then perspective_points_box draws it in the view).
void perspective_state_panel(const PerspectiveSession& s, bool table_in_view, const PanelLayout& layout);

// The points' table across the view's foot (eye space, w and the transformed x′, y′, z′), where a class reads it
// whole; `points_box_share` of the view's height.
inline constexpr float points_box_share = 0.375f;
void perspective_points_box(const PerspectiveSession& s, float view_w, float view_h);

}  // namespace hsr::viz
