// SPDX-License-Identifier: MIT
// The state panel of a back-face culling lesson: every face with its value and verdict.
#pragma once

#include "panels/lesson_panels.h"
#include "state/backface_session.h"

namespace hsr::viz {

// The counts, and the faces' table unless it is in the view (`table_in_view`: backface_faces_box).
void backface_state_panel(const BackfaceSession& s, bool table_in_view, const PanelLayout& layout);
// Every face with its value and verdict, in the view's right part (panels/view_side_box.h).
inline constexpr float faces_box_share = 0.45f;  // of the view's width: a column per number, a word per verdict
void backface_faces_box(const BackfaceSession& s, float view_w, float view_h);

}  // namespace hsr::viz
