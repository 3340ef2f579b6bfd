// SPDX-License-Identifier: MIT
// The state panel of a BSP lesson: the statistics line and the tree as nodes and edges.
#pragma once

#include "panels/lesson_panels.h"
#include "panels/ui_actions.h"
#include "state/bsp_session.h"

namespace hsr::viz {

// With the tree's controls: DisplayBSP's order, the splitter rule, and the insertion order (reverse, shuffle); the
// tree itself too unless it is in the view (`tree_in_view`: bsp_tree_canvas).
void bsp_state_panel(const BspSession& s, bool tree_in_view, const PanelLayout& layout, UiActions& out);

// Over the view's lower part: what DisplayBSP has painted so far, seen from the eye (a 3D scene: the camera's
// image at the lower left; a 2D plan: the first-person strip across the view's foot). Returns the height it takes
// from the view's foot, for the framing to keep the plan above it.
void bsp_painted_canvas(const BspSession& s, float view_w, float view_h, bool driving);
// The tree, in the view's right part (panels/view_side_box.h; in a 2D plan above the first-person strip), where a
// class sees it whole; the column's state box keeps its counts and controls.
void bsp_tree_canvas(const BspSession& s, float view_w, float view_h);
// The height of the first-person strip of a 2D plan in a view `view_h` points tall (its caption included).
float strip_height(float view_h);

}  // namespace hsr::viz
