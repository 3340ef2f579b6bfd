// The panels of a culling lesson: the pipeline (one row per stage: primitives in, left out, passed on, time, and a
// bar of what it leaves out), what the machine has done so far, the void space of each object's bounding volumes
// (bounds lesson), and the Z-pyramid's levels as images (hierarchical z-buffer lesson).
#pragma once

#include "panels/lesson_panels.h"
#include "state/culling_session.h"

namespace hsr::viz {

void culling_state_panel(const CullingLesson& s, const PanelLayout& layout);
// Over the view area: the Z-pyramid's finest levels, built from what has been rendered so far (Hi-Z lesson only).
void culling_canvas(const CullingLesson& s, float x, float y, float w, float h);

}  // namespace hsr::viz
