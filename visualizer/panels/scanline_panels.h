// SPDX-License-Identifier: MIT
// The panels of a scan-line lesson: the image filled line by line with the current line, its active edges and
// their crossings (classic: where the planes were compared, and the extra intersections); the edge table with the
// active edges marked, and the in/out flags.
#pragma once

#include "panels/lesson_panels.h"
#include "state/scanline_session.h"

namespace hsr::viz {

void scanline_canvas(const ScanLineSession& s, float x, float y, float w, float h);
// The hybrid's edge table with the in/out flags; the classic's edge table in the notes' fields (x, y_max, Δx) and its
// polygon table (plane equation, in/out), with the switch for the extra intersections where polygons pierce.
void scanline_state_panel(const ScanLineSession& s, const PanelLayout& layout, UiActions& out);

}  // namespace hsr::viz
