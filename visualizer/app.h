// SPDX-License-Identifier: MIT
// The window: SDL2 + OpenGL 3.3 core + Dear ImGui around one lesson being played.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hsr::viz {

struct AppOptions {
    std::string lesson_path;
    std::optional<std::string> algorithm;      // overrides the lesson's
    std::optional<std::string> screenshot;     // write a PNG of the window after `frames` frames, then exit
    int frames = 60;
    std::optional<std::string> record_dir;     // headless: a PNG per step and the trace, then exit
    int width = 1280, height = 800;
    bool size_given = false;                   // --size: this size, not the one remembered from the last run
    bool autoplay = false;                     // start playing (the screenshot and record modes step on their own)
    std::optional<std::string> gif;            // headless: an animated GIF of steps gif_from … gif_to, then exit
    std::size_t gif_from = 0, gif_to = 60;
    bool gif_half = false;                     // GIF frames at half size (smaller files, text harder to read)
    std::optional<std::string> frame_log;      // one line per frame: its time in ms (and the median printed at exit)
    bool projector = false;                    // fullscreen, larger type for the back row, high contrast
    float scale = 0;                           // the size of type and panels (1 = normal); 0: 1.3 for a projector, else
                                               // the screen's (2 on a high-DPI screen)
    std::optional<std::size_t> start_step;     // open the lesson at this step (a link's)
    std::optional<std::string> language;       // narrate in this language rather than the one last chosen (a link's)
    std::vector<std::string> keys;             // pressed one per frame through SDL's event queue, e.g. "Shift+Right"
};

// Runs until the window closes (or the screenshot / recording is done). Returns the process exit code.
int run_app(const AppOptions& options);

}  // namespace hsr::viz
