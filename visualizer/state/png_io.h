// SPDX-License-Identifier: MIT
// Writing images: colour as 8-bit RGB PNG (stb), visible primitive ids as 16-bit grey PNG (libpng).
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
// One 16-bit grey sample per pixel: the scene's id of the visible primitive, 0 for background. False when it
// cannot be written, or when an id does not fit 16 bits.
bool write_ids_png(const std::string& path, const algo::Image& image);

}  // namespace hsr::viz
