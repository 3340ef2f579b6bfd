// The panel of a depth-sort lesson: the decision table of the pair under examination (each test tried, its
// outcome and the numbers that decided it) and the display list.
#pragma once

#include "panels/lesson_panels.h"
#include "state/depth_sort_session.h"

namespace hsr::viz {

void depth_sort_state_panel(const DepthSortSession& s, const PanelLayout& layout);

}  // namespace hsr::viz
