// SPDX-License-Identifier: MIT
// The command line's image of visible primitive ids (`hsrviz render --ids`), as 16-bit grey PNG (libpng: stb writes
// 8 bits only). Only the command line links libpng; the window writes its pictures with stb (state/png_io.h).
#pragma once

#include <string>

#include "raster/image.h"

namespace hsr::viz {

// One 16-bit grey sample per pixel: the scene's id of the visible primitive, 0 for background. False when it
// cannot be written, or when an id does not fit 16 bits.
bool write_ids_png(const std::string& path, const algo::Image& image);

}  // namespace hsr::viz
