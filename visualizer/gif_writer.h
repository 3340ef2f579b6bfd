// SPDX-License-Identifier: MIT
// An animated GIF of the window, frame by frame (giflib): each frame quantised to its own 256-colour palette,
// looping for ever, for a teacher's slides.
#pragma once

#include <string>
#include <vector>

struct GifFileType;

namespace hsr::viz {

class GifWriter {
public:
    GifWriter(const std::string& path, int width, int height, int delay_centiseconds);
    ~GifWriter();
    GifWriter(const GifWriter&) = delete;
    GifWriter& operator=(const GifWriter&) = delete;
    bool ok() const { return gif_ != nullptr; }
    // RGBA pixels, width × height, the top row first.
    bool add_frame(const std::vector<unsigned char>& rgba);
    bool close();  // false when the file could not be finished
    int frames() const { return frames_; }

private:
    GifFileType* gif_ = nullptr;
    int width_, height_, delay_, frames_ = 0;
};

}  // namespace hsr::viz
