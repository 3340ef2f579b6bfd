// SPDX-License-Identifier: MIT
// The panels of a z-merge lesson: part A, part B and the merged image side by side, and the pixel merged last.
#pragma once

#include "panels/lesson_panels.h"
#include "state/zmerge_session.h"

namespace hsr::viz {

void zmerge_canvas(const ZMergeSession& s, float x, float y, float w, float h);
void zmerge_state_panel(const ZMergeSession& s, const PanelLayout& layout);

}  // namespace hsr::viz
