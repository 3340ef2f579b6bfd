// Pictures of the window: a PNG of the frame just drawn, a GIF frame at half size, and E's export (the window, the
// trace and the scene) into hsrviz-export/.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "state/session.h"

namespace hsr::viz {

// The drawable's pixels as a PNG (top row first). False when it cannot be written.
bool write_png(const std::string& path, int width, int height);
// The drawable's pixels at half size (each 2×2 block averaged), RGBA, the top row first.
std::vector<unsigned char> half_size_pixels(int width, int height);
// E: the window as a PNG, the lesson's trace, and its scene as TOML, into hsrviz-export/; says what it wrote.
// Returns what it did, as a sentence for the window's note ("exported …" or "could not export all of …").
std::string export_lesson(const Session& s, const std::string& path, const std::optional<std::string>& algorithm, int width, int height);

}  // namespace hsr::viz
