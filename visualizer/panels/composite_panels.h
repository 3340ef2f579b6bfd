// SPDX-License-Identifier: MIT
// Alpha compositing's canvas (the layers as glass over a checkerboard, the two composites, Porter and Duff's
// coverage squares) and its state box (the formula of the current step with its numbers, the operators' table).
#pragma once

#include "panels/lesson_panels.h"
#include "state/composite_session.h"

namespace hsr::viz {

void composite_canvas(const CompositeSession& s, float x, float y, float w, float h);
void composite_state_panel(const CompositeSession& s, const PanelLayout& layout);

}  // namespace hsr::viz
