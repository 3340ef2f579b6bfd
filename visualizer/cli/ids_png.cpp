// SPDX-License-Identifier: MIT
#include "cli/ids_png.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <vector>

#include <png.h>

#include "core/work_meter.h"

namespace hsr::viz {

namespace {

enum class Written { whole, failed, stopped };

// Rows written one at a time by libpng into `f`, the stop flag looked at between rows.
Written write_rows_to(FILE* f, const algo::Image& image, int bit_depth, int colour_type, std::size_t row_bytes,
                      const std::function<void(int, png_byte*)>& fill, const std::atomic<bool>* stop) {
    std::vector<png_byte> row(row_bytes);  // before setjmp: a longjmp must not skip a destructor
    // errors said by us ("cannot write …", "stopped"), not printed by libpng as "libpng error: …" first
    const auto quiet_error = [](png_structp p, png_const_charp) { png_longjmp(p, 1); };
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, quiet_error, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    volatile bool stopped = false;  // read after a longjmp
    if (!png || !info || setjmp(png_jmpbuf(png))) {  // libpng reports errors by longjmp
        png_destroy_write_struct(&png, &info);
        return stopped ? Written::stopped : Written::failed;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), bit_depth, colour_type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < image.height; ++y) {
        if (stop && stop->load(std::memory_order_relaxed)) {
            stopped = true;
            png_error(png, "stopped");  // longjmps to the cleanup above
        }
        fill(y, row.data());
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return Written::whole;
}

// A 16384² picture takes half a minute to compress, and a Ctrl+C then waited for all of it (issue 53, item 12): a
// stop between rows throws WorkStopped. A file not written whole is removed (not a device such as /dev/full).
bool write_rows(const std::string& path, const algo::Image& image, int bit_depth, int colour_type, std::size_t row_bytes,
                const std::function<void(int, png_byte*)>& fill, const std::atomic<bool>* stop) {
    std::error_code ec;
    const bool device = std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec);
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const Written w = write_rows_to(f, image, bit_depth, colour_type, row_bytes, fill, stop);
    const bool closed = std::fclose(f) == 0;  // a full disk shows at the flush in fclose
    if (w == Written::whole && closed) return true;
    if (!device) std::filesystem::remove(path, ec);
    if (w == Written::stopped) throw algo::WorkStopped();
    return false;
}

}  // namespace

bool write_colour_png(const std::string& path, const algo::Image& image, const std::atomic<bool>* stop) {
    const std::size_t row_bytes = std::size_t(image.width) * 3;
    return write_rows(path, image, 8, PNG_COLOR_TYPE_RGB, row_bytes,
                      [&](int y, png_byte* row) { std::memcpy(row, image.rgb.data() + std::size_t(y) * row_bytes, row_bytes); }, stop);
}

bool write_ids_png(const std::string& path, const algo::Image& image, const std::atomic<bool>* stop) {
    for (algo::SceneId id : image.ids)
        if (id < 0 || id > 65535) return false;  // a 16-bit sample cannot hold it
    return write_rows(path, image, 16, PNG_COLOR_TYPE_GRAY, std::size_t(image.width) * 2, [&](int y, png_byte* row) {
        for (int x = 0; x < image.width; ++x) {  // PNG samples are big-endian
            const auto id = std::uint16_t(image.id(x, y));  // 0 … 65535, checked above
            row[2 * std::size_t(x)] = png_byte(id >> 8);
            row[2 * std::size_t(x) + 1] = png_byte(id & 0xff);
        }
    }, stop);
}

}  // namespace hsr::viz
