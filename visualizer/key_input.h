// SPDX-License-Identifier: MIT
// The keyboard and the mouse as the window reads them: a key press as the actions it asks for (keys_panel.cpp lists
// them for F1), and a mouse event as a screen's gesture input.
#pragma once

#include <SDL.h>

#include <optional>

#include "panels/ui_actions.h"
#include "screens/screen.h"

namespace hsr::viz {

// What a key press asks for (nothing for other events).
void actions_of_key(const SDL_Event& e, UiActions& a);
// A mouse button or motion event as a screen's gesture input; `over_ui`: ImGui has the mouse.
std::optional<Pointer> pointer_of(const SDL_Event& e, bool over_ui);

}  // namespace hsr::viz
