// SPDX-License-Identifier: MIT
// The perspective transform's state box: where the warp is, each point before and after the divide by w, the pair
// under comparison with its numbers both ways, and what each way divides.
#pragma once

#include "panels/lesson_panels.h"
#include "state/perspective_session.h"

namespace hsr::viz {

void perspective_state_panel(const PerspectiveSession& s, const PanelLayout& layout);

}  // namespace hsr::viz
