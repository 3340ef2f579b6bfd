// SPDX-License-Identifier: MIT
// The panels of a scan-line lesson: the image filled line by line with the current line, its active edges and
// their crossings; the edge table with the active edges marked, and the in/out flags.
#pragma once

#include "panels/lesson_panels.h"
#include "state/scanline_session.h"

namespace hsr::viz {

void scanline_canvas(const ScanLineSession& s, float x, float y, float w, float h);
void scanline_state_panel(const ScanLineSession& s, const PanelLayout& layout);

}  // namespace hsr::viz
