// SPDX-License-Identifier: MIT
// The command line's pictures: the colour image, and the image of visible primitive ids (`hsrviz render --ids`) as
// 16-bit grey PNG (libpng: stb writes 8 bits only, and all rows in one call). Only the command line links libpng; the window writes its pictures with stb (state/png_io.h).
#pragma once

#include <atomic>
#include <string>

#include "raster/image.h"

namespace hsr::viz {

// One 16-bit grey sample per pixel: the scene's id of the visible primitive, 0 for background. False when it
// cannot be written, or when an id does not fit 16 bits.
bool write_ids_png(const std::string& path, const algo::Image& image, const std::atomic<bool>* stop = nullptr);
// The picture as 8-bit RGB, written row by row: `stop` (Ctrl+C) is looked at between rows, and then the file is
// removed and algo::WorkStopped thrown. False when it cannot be written (a file not written whole is removed).
bool write_colour_png(const std::string& path, const algo::Image& image, const std::atomic<bool>* stop = nullptr);

}  // namespace hsr::viz
