// The state panel of a back-face culling lesson: every face with its value and verdict.
#pragma once

#include "panels/lesson_panels.h"
#include "state/cull_session.h"

namespace hsr::viz {

void cull_state_panel(const CullSession& s, const PanelLayout& layout);

}  // namespace hsr::viz
