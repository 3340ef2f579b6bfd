// SPDX-License-Identifier: MIT
// What the window tells about itself: where the player stands (the screenshot's line, the page's state line), and
// the answers to the page's script's questions (platform.h answer_queries).
#pragma once

#include <string>

#include "frame_drawing.h"
#include "lesson_play.h"

namespace hsr::viz {

// "step 3 of 64, paused, question open" (empty when no lesson loaded).
std::string player_state(const LessonPlay& lp);

// The file playing ("lesson"), the error shown instead of it ("error"), the narration's language ("language"), the
// practice score over every topic ("practice"), the played trace ("trace"), the type's size in points
// ("type_size"), the last frame's layout problems ("layout"), where a gesture's point is in the window
// ("window_point X Y": "x y", as --keys' gestures name points); "" to anything else.
std::string page_answer(LessonPlay& lp, const Renderer& r, const std::string& question);

}  // namespace hsr::viz
