// The state panel of a BSP lesson: the statistics line and the tree as nodes and edges.
#pragma once

#include "panels/lesson_panels.h"
#include "state/bsp_session.h"

namespace hsr::viz {

void bsp_state_panel(const BspSession& s, const PanelLayout& layout);

}  // namespace hsr::viz
