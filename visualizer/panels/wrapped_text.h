// SPDX-License-Identifier: MIT
// Text wrapped at spaces only. ImGui's own wrapping also breaks after '.' and ',', which splits numbers in the
// middle ("(-1.↵73205"); a sentence of this tool is full of numbers.
#pragma once

#include <string_view>

#include <imgui.h>

#include "state/text_wrap.h"

namespace hsr::viz {

// Draws `text` wrapped at spaces to the window's content width, in `colour` (the current text colour by default).
void wrapped_text(std::string_view text);
void wrapped_text(std::string_view text, const ImVec4& colour);
// How tall wrapped_text(text) would be in the current window (its lines with their spacing).
float wrapped_height(std::string_view text);

}  // namespace hsr::viz
