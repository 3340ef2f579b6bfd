// SPDX-License-Identifier: MIT
// The panels of a culling lesson: the pipeline (one row per stage: primitives in, left out, passed on, time, and a
// bar of what it leaves out), what the machine has done so far, the void space of each object's bounding volumes
// (bounds lesson), and the Z-pyramid's levels as images (hierarchical z-buffer lesson).
#pragma once

#include <cstdint>
#include <vector>

#include "panels/lesson_panels.h"
#include "state/culling_session.h"
#include "state/state_colours.h"
#include "state/walkthrough.h"

namespace hsr::viz {

// `legend_in_view`: the screen draws the legend of the boxes' colours in the view (view_legend), else it is here.
void culling_state_panel(const CullingLesson& s, const PanelLayout& layout, bool legend_in_view = false);
// The colours of the boxes (and lines) the view shows now, each with its word.
std::vector<StateColour> culling_legend_entries(const CullingView& v);
// Walking through the scene (W): each stage with a switch, what reached it, what it left out and its time, the
// frame's time, the Hi-Z stage's frame-to-frame coherence; the switches fill in `out`.
void walk_panel(const Walkthrough& walk, const PanelLayout& layout, UiActions& out);
// Over the view area: the Z-pyramid's finest levels, built from `depth`, the depth buffer of what has been rendered
// so far (rendered_depth: the Hi-Z lesson).
void zpyramid_canvas(const CullingView& view, const std::vector<std::uint32_t>& depth, float x, float y, float w, float h);

}  // namespace hsr::viz
