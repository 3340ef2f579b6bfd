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
// `selected`: the pixel whose list the state box opens (a click on the grid), framed white.
void abuffer_canvas(const ABufferSession& s, std::optional<std::pair<int, int>> selected, float x, float y, float w, float h);
void abuffer_state_panel(const ABufferSession& s, std::optional<std::pair<int, int>> selected, const PanelLayout& layout);

}  // namespace hsr::viz
