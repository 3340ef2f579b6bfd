// SPDX-License-Identifier: MIT
// Roberts' state box: the edge under test, the body it is compared with and the part that body hides, the counts.
#pragma once

#include "panels/lesson_panels.h"
#include "state/roberts_session.h"

namespace hsr::viz {

void roberts_state_panel(const RobertsSession& s, const PanelLayout& layout);

}  // namespace hsr::viz
