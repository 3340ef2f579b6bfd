// Text wrapped at spaces only. ImGui's own wrapping also breaks after '.' and ',', which splits numbers in the
// middle ("(-1.↵73205"); a sentence of this tool is full of numbers.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <imgui.h>

namespace hsr::viz {

// The lines of `text` at most `width` wide as `measure` measures them, broken at spaces (and at '\n'); a word wider
// than a line gets a line of its own, broken inside only as a last resort, at the width.
std::vector<std::string> wrap_at_spaces(std::string_view text, float width,
                                        const std::function<float(std::string_view)>& measure);

// Text as written in a lesson file's multi-line string: a single line break is a space (the author's editor wrapped
// there), an empty line a paragraph break.
std::string reflow(std::string_view text);

// Draws `text` wrapped at spaces to the window's content width, in `colour` (the current text colour by default).
void wrapped_text(std::string_view text);
void wrapped_text(std::string_view text, const ImVec4& colour);

}  // namespace hsr::viz
