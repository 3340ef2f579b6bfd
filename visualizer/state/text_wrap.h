// SPDX-License-Identifier: MIT
// Text wrapped at spaces only, and lesson text reflowed: the arithmetic of the window's wrapped text, without ImGui
// (the measure of a string is passed in), so that tests can drive it.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace hsr::viz {

// The lines of `text` at most `width` wide as `measure` measures them, broken at spaces (and at '\n'); a word wider
// than a line gets a line of its own, broken inside only as a last resort, at the width (`forced` counts those).
std::vector<std::string> wrap_at_spaces(std::string_view text, float width,
                                        const std::function<float(std::string_view)>& measure, int* forced = nullptr);

// Text as written in a lesson file's multi-line string: a single line break is a space (the author's editor wrapped
// there), an empty line a paragraph break.
std::string reflow(std::string_view text);

}  // namespace hsr::viz
