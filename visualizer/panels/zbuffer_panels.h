// SPDX-License-Identifier: MIT
// The panels of a z-buffer lesson: the fat-pixel frame buffer beside the depth buffer as a heat map, with the
// polygon, span and pixel under way; the depth-precision diagram; and the format, near and far controls.
#pragma once

#include "panels/fat_pixels.h"
#include "panels/lesson_panels.h"
#include "state/zbuffer_session.h"

namespace hsr::viz {

// Fills the view area (x, y, w, h in window points, top-left origin).
void zbuffer_canvas(const ZBufferSession& s, float x, float y, float w, float h);
// Where the canvas in (x, y, w, h) draws the frame buffer (FatGrid: panels/fat_pixels.h), so that the window's
// mouse can be read in pixels of the grid (editing).
FatGrid zbuffer_frame_grid(const ZBufferSession& s, float x, float y, float w, float h);
// `in_3d`: whether the view shows the scene in 3D (the checkbox's state)
void zbuffer_state_panel(const ZBufferSession& s, bool in_3d, const PanelLayout& layout, UiActions& out);

}  // namespace hsr::viz
