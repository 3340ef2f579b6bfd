// SPDX-License-Identifier: MIT
// What a run writes of its frames: --record's PNG per step, E's export, --gif's frames, --screenshot's PNG (when
// every scripted key is in and the column has settled) with the lines that say what it shows, and --frame-log's
// times. The loop calls it after each frame is drawn and once at the end.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "app.h"
#include "gif_writer.h"
#include "lesson_play.h"

namespace hsr::viz {

class FrameCapture {
public:
    // Before the first frame: --gif's first step sought, --record's folder made. False: nothing to run (said why;
    // `exit_code` set).
    bool begin(LessonPlay& lp, const AppOptions& o, int& exit_code);
    // After frame number `frame` (from 1) is drawn into the drawable of width × height pixels; `keys_pressed`: every
    // scripted key was pressed. Clears `running` when the run has written all it was asked to.
    void after_draw(LessonPlay& lp, const AppOptions& o, std::uint64_t frame, int width, int height, bool keys_pressed, bool& running,
                    int& exit_code);
    // After the frame is on the screen: its time, for --frame-log.
    void after_swap(const AppOptions& o);
    // At the end: the frame log written, the GIF closed, what was written said.
    void finish(const LessonPlay& lp, const AppOptions& o, std::uint64_t frames, int& exit_code);

private:
    std::optional<GifWriter> gif_;  // half the drawable's size with --gif-half (made at the first frame)
    bool gif_failed_ = false;
    bool record_folder_made_ = true;
    std::vector<double> frame_ms_;  // --frame-log
    std::uint64_t frame_start_ = 0;
};

}  // namespace hsr::viz
