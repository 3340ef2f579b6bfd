// SPDX-License-Identifier: MIT
// What differs between the desktop window and the same window in a browser, in one place: the OpenGL profile and
// its shading language, how frames are driven, and whether the window may start threads. The desktop's answers are
// in platform_desktop.cpp; the browser's in web/platform_web.cpp (web/CMakeLists.txt builds that one instead).
#pragma once

#include <functional>
#include <string>

namespace hsr::viz {

struct GlProfile {
    int major = 3, minor = 3;
    bool es = false;                    // OpenGL ES (WebGL 2) rather than a core profile
    const char* glsl_version = "";      // every shader's first line ("#version 330 core")
    const char* fragment_preamble = ""; // what a fragment shader needs before its body (ES: a float precision)
    bool browser_paced = false;         // a browser's animation frames pace the window (no swap interval to set)
};
const GlProfile& gl_profile();

// Calls frame() until it returns false. The desktop loops; a browser calls it once per animation frame and never
// returns to the caller (whose locals stay alive: the page runs until it is closed).
void run_frames(const std::function<bool()>& frame);

// Can the window start a thread (the run-time report's measurement in the background)? A browser page without
// worker threads cannot: the work then runs in the frame that asks for it.
bool can_start_threads();

// The player's state in a line a page's script can read ("step 3 of 64, paused, question open, score 1 of 2"), once
// a frame: the browser's tests read it; the desktop has no use for it.
void publish_state(const std::string& line);

}  // namespace hsr::viz
