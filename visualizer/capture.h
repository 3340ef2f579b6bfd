// SPDX-License-Identifier: MIT
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
// The drawable's pixels, RGBA, the top row first: at full size, or at half (each 2×2 block averaged).
std::vector<unsigned char> frame_pixels(int width, int height, bool half);
// E: the window as a PNG, the lesson's trace, and its scene as TOML, into hsrviz-export/; says what it wrote.
// Returns what it did, as a sentence for the window's note ("exported …" or "could not export all of …").
// `written` gets the files written (a browser offers them as downloads). After an edit (`edited`: the scene as the
// student left it) the scene and the trace are the edited scene's, as the PNG shows it.
std::string export_lesson(const Session& s, const std::string& path, const std::optional<std::string>& algorithm,
                          const std::optional<algo::Scene>& edited, int width, int height, std::vector<std::string>& written);

}  // namespace hsr::viz
