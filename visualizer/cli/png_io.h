// Writing images: colour as 8-bit RGB PNG (stb), visible primitive ids as 16-bit grey PNG (libpng).
#pragma once

#include <string>

#include "raster/image.h"

namespace hsr::viz {

bool write_rgb_png(const std::string& path, const algo::Image& image);
// One 16-bit grey sample per pixel: the scene's id of the visible primitive, 0 for background. False when it
// cannot be written, or when an id does not fit 16 bits.
bool write_ids_png(const std::string& path, const algo::Image& image);

}  // namespace hsr::viz
