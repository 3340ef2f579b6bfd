// SPDX-License-Identifier: MIT
// The general forms' canvas (the floor plan with the eye, the field of view and the segments, and the two images the
// forms render, one row of pixels each) and its state box (where each form is, the counts against P·(P − 1) and p·P).
#pragma once

#include "panels/lesson_panels.h"
#include "state/forms_session.h"

namespace hsr::viz {

void forms_canvas(const FormsSession& s, float x, float y, float w, float h);
void forms_state_panel(const FormsSession& s, const PanelLayout& layout);

}  // namespace hsr::viz
