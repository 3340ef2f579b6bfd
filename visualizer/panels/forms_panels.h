// SPDX-License-Identifier: MIT
// The general forms' canvas (the floor plan with the eye, the field of view and the segments, and the two images the
// forms render, one row of pixels each) and its state box (where each form is, the counts against P·(P − 1) and p·P).
#pragma once

#include "panels/lesson_panels.h"
#include "state/forms_session.h"

namespace hsr::viz {

void forms_canvas(const FormsSession& s, float x, float y, float w, float h);
// The phase and the counts, and the segments' table unless it is in the view (`table_in_view`: forms_table_box).
void forms_state_panel(const FormsSession& s, bool table_in_view, const PanelLayout& layout);
// The segments' table (each one's image and visible share) in the view's right part (panels/view_side_box.h).
inline constexpr float forms_table_share = 0.34f;
void forms_table_box(const FormsSession& s, float view_w, float view_h);

}  // namespace hsr::viz
