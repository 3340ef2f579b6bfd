// SPDX-License-Identifier: MIT
// The panels of an A-buffer lesson: the fat pixels with each pixel's sub-samples coloured by the nearest fragment
// covering them (then the pixel's resolved colour), the same image with one sample per pixel beside it, and a state
// box that opens one pixel's fragment list with each fragment's coverage mask.
#pragma once

#include <optional>
#include <utility>

#include "panels/fat_pixels.h"
#include "panels/lesson_panels.h"
#include "state/abuffer_session.h"

namespace hsr::viz {

// Where the canvas in (x, y, w, h) draws the A-buffer's grid.
FatGrid abuffer_grid(const ABufferSession& s, float x, float y, float w, float h);
// `selected`: the pixel whose list is opened (a click on the grid), framed white. The list of the pixel at work (or
// the selected one) is drawn in the view, right of the one-sample image, when it has the room there (true): else
// the state box holds it (`list_in_view` false), where a short column scrolled its last fragments out of sight.
bool abuffer_canvas(const ABufferSession& s, std::optional<std::pair<int, int>> selected, float x, float y, float w, float h);
void abuffer_state_panel(const ABufferSession& s, std::optional<std::pair<int, int>> selected, bool list_in_view, const PanelLayout& layout);

}  // namespace hsr::viz
