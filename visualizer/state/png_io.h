// SPDX-License-Identifier: MIT
// Writing images: colour as 8-bit RGB PNG (stb). (The command line's 16-bit id images: cli/ids_png.h.)
#pragma once

#include <string>
#include <string_view>

#include "raster/image.h"

namespace hsr::viz {

// The bytes as the file's whole content; false when the file cannot be made or a write fails (a full disk).
bool write_bytes(const std::string& path, std::string_view bytes);
// Pixels (`channels` per pixel, rows top first, or bottom first as GL reads them) as a PNG; false when not written.
bool write_png(const std::string& path, int width, int height, int channels, const unsigned char* pixels, bool bottom_up);
bool write_rgb_png(const std::string& path, const algo::Image& image);

}  // namespace hsr::viz
