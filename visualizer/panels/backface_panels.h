// SPDX-License-Identifier: MIT
// The state panel of a back-face culling lesson: every face with its value and verdict.
#pragma once

#include "panels/lesson_panels.h"
#include "state/backface_session.h"

namespace hsr::viz {

void backface_state_panel(const BackfaceSession& s, const PanelLayout& layout);

}  // namespace hsr::viz
