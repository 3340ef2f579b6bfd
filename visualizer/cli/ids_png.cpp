// SPDX-License-Identifier: MIT
#include "cli/ids_png.h"

#include <cstdint>
#include <cstdio>
#include <vector>

#include <png.h>

namespace hsr::viz {

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
