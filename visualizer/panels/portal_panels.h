// SPDX-License-Identifier: MIT
// The panels of a cells-and-portals lesson: the floor plan (cells, portals, the sightline being tested or the eye
// with its narrowing frusta as wedges; drag the eye and the traversal reruns at once), and the state panel with
// the PVS matrix, the stab tree and the counts of polygons drawn and culled per reason.
#pragma once

#include "panels/lesson_panels.h"
#include "state/portal_session.h"

namespace hsr::viz {

// Over the whole view area (x, y, w, h); fills out.move_eye while the eye is dragged.
void portal_plan_canvas(const PvsSession& s, float x, float y, float w, float h);
void portal_plan_canvas(const PortalRenderSession& s, float x, float y, float w, float h, UiActions& out);
void pvs_state_panel(const PvsSession& s, const PanelLayout& layout);
void portal_state_panel(const PortalRenderSession& s, bool three_d, const PanelLayout& layout, UiActions& out);

}  // namespace hsr::viz
