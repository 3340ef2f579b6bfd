// SPDX-License-Identifier: MIT
#include "gif_writer.h"

#include <gif_lib.h>

namespace hsr::viz {

GifWriter::GifWriter(const std::string& path, int width, int height, int delay) : width_(width), height_(height), delay_(delay) {
    int error = 0;
    gif_ = EGifOpenFileName(path.c_str(), false, &error);
    if (!gif_) return;
    EGifSetGifVersion(gif_, true);
    if (EGifPutScreenDesc(gif_, width, height, 8, 0, nullptr) == GIF_ERROR) {
        EGifCloseFile(gif_, &error);
        gif_ = nullptr;
        return;
    }
    // NETSCAPE2.0: loop for ever
    static unsigned char app[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
    static unsigned char loop[] = {1, 0, 0};
    EGifPutExtensionLeader(gif_, APPLICATION_EXT_FUNC_CODE);
    EGifPutExtensionBlock(gif_, sizeof app, app);
    EGifPutExtensionBlock(gif_, sizeof loop, loop);
    EGifPutExtensionTrailer(gif_);
}

GifWriter::~GifWriter() { close(); }

bool GifWriter::add_frame(const std::vector<unsigned char>& rgba) {
    if (!gif_) return false;
    const std::size_t n = std::size_t(width_) * std::size_t(height_);
    std::vector<GifByteType> r(n), g(n), b(n), index(n);
    for (std::size_t k = 0; k < n; ++k) r[k] = rgba[4 * k], g[k] = rgba[4 * k + 1], b[k] = rgba[4 * k + 2];
    int colours = 256;
    std::vector<GifColorType> palette(256);
    if (GifQuantizeBuffer(unsigned(width_), unsigned(height_), &colours, r.data(), g.data(), b.data(), index.data(), palette.data()) == GIF_ERROR)
        return false;
    ColorMapObject* map = GifMakeMapObject(256, palette.data());
    // the frame's delay, in hundredths of a second
    unsigned char control[] = {0, static_cast<unsigned char>(delay_ & 0xff), static_cast<unsigned char>(delay_ >> 8), 0};
    bool ok = EGifPutExtension(gif_, GRAPHICS_EXT_FUNC_CODE, sizeof control, control) != GIF_ERROR &&
              EGifPutImageDesc(gif_, 0, 0, width_, height_, false, map) != GIF_ERROR;
    for (int y = 0; ok && y < height_; ++y) ok = EGifPutLine(gif_, index.data() + std::size_t(y) * std::size_t(width_), width_) != GIF_ERROR;
    GifFreeMapObject(map);
    frames_ += ok;
    return ok;
}

bool GifWriter::close() {
    if (!gif_) return false;
    int error = 0;
    const bool ok = EGifCloseFile(gif_, &error) != GIF_ERROR;
    gif_ = nullptr;
    return ok;
}

}  // namespace hsr::viz
