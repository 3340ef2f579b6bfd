// SPDX-License-Identifier: MIT
// What the window remembers between runs (state/window_settings.h), taken from the window as it is now and
// written when it changes.
#pragma once

#include <string>

#include "app.h"
#include "lesson_play.h"
#include "state/window_settings.h"
#include "window.h"

namespace hsr::viz {

// The column, the language, the practice scores and the type's size always; the window's size and place
// (`with_place`) at the end of a run a person sized it in.
WindowSettings settings_now(const WindowSettings& before, const LessonPlay& lp, const Window& w, const AppOptions& o, bool with_place);
// Writes `now` to `path` when it differs from `saved` (saying once why it could not), and keeps it as `saved`.
void remember(const std::string& path, WindowSettings& saved, const WindowSettings& now);

}  // namespace hsr::viz
