// SPDX-License-Identifier: MIT
// A frame drawn from inside long work (the meter's teller, five times a second once it has lasted 0.3 s): the
// progress box over an empty view. The input is only looked at, not taken: Esc stops the work, closing the window
// stops it and quits, and every event stays queued for the frame after the work (a key pressed meanwhile is not
// lost; a scripted Escape is pressed now, as a teacher's would be, the other scripted keys wait for their frames).
#pragma once

#include <cstddef>

#include "app.h"
#include "core/work_meter.h"
#include "lesson_play.h"
#include "window.h"

namespace hsr::viz {

void work_frame(const algo::WorkProgress& p, Window& w, LessonPlay& lp, const AppOptions& o, std::size_t& next_key, bool& quit);

// SDL's offscreen driver: no display paces the frames (the window finishes each frame's GL work itself).
bool offscreen_driver();

}  // namespace hsr::viz
