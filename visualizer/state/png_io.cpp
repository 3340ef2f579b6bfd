// SPDX-License-Identifier: MIT
#include "state/png_io.h"

#include <cstdio>
#include <vector>

#include <png.h>
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

bool write_ids_png(const std::string& path, const algo::Image& image) {
    for (algo::SceneId id : image.ids)
        if (id < 0 || id > 65535) return false;  // a 16-bit sample cannot hold it
    std::vector<png_byte> row(std::size_t(image.width) * 2);  // before setjmp: a longjmp must not skip a destructor
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info || setjmp(png_jmpbuf(png))) {  // libpng reports errors by longjmp
        png_destroy_write_struct(&png, &info);
        std::fclose(f);
        return false;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 16, PNG_COLOR_TYPE_GRAY,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {  // PNG samples are big-endian
            const auto id = std::uint16_t(image.id(x, y));  // 0 … 65535, checked above
            row[2 * std::size_t(x)] = png_byte(id >> 8);
            row[2 * std::size_t(x) + 1] = png_byte(id & 0xff);
        }
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return std::fclose(f) == 0;
}

}  // namespace hsr::viz
