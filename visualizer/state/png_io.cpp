// SPDX-License-Identifier: MIT
#include "state/png_io.h"

#include <cstdio>

#include <stb/stb_image_write.h>

namespace hsr::viz {

bool write_bytes(const std::string& path, std::string_view bytes) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    return std::fclose(f) == 0 && written;  // a full disk shows at the flush in fclose
}

bool write_png(const std::string& path, int width, int height, int channels, const unsigned char* pixels, bool bottom_up) {
    // stb's own file writer does not check its writes: encode in memory, then write and check
    std::string png;
    stbi_flip_vertically_on_write(bottom_up ? 1 : 0);
    const int ok = stbi_write_png_to_func([](void* to, void* data, int size) { static_cast<std::string*>(to)->append(static_cast<const char*>(data), std::size_t(size)); },
                                          &png, width, height, channels, pixels, width * channels);
    return ok != 0 && write_bytes(path, png);
}

bool write_rgb_png(const std::string& path, const algo::Image& image) {
    return write_png(path, image.width, image.height, 3, image.rgb.data(), false);
}

}  // namespace hsr::viz
