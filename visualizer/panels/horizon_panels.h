// SPDX-License-Identifier: MIT
// The floating horizon's canvas (the screen the curves are drawn on, with the two horizons) and its state box.
#pragma once

#include "panels/lesson_panels.h"
#include "state/horizon_session.h"

namespace hsr::viz {

void horizon_canvas(const HorizonSession& s, float x, float y, float w, float h);
void horizon_state_panel(const HorizonSession& s, const PanelLayout& layout);

}  // namespace hsr::viz
