// SPDX-License-Identifier: MIT
// The state panel of a clipping lesson.
#pragma once

#include "panels/lesson_panels.h"
#include "state/clip_session.h"

namespace hsr::viz {

void clip_state_panel(const ClipSession& s, const PanelLayout& layout);

}  // namespace hsr::viz
