// SPDX-License-Identifier: MIT
// The browser's platform (platform.h): WebGL 2 (OpenGL ES 3.0), frames driven by the browser's animation frames, no
// threads (the page is built without workers).
#include <emscripten.h>

#include <string>

#include "platform.h"

namespace hsr::viz {

const GlProfile& gl_profile() {
    static const GlProfile profile{3, 0, true, "#version 300 es", "precision mediump float;\n", true};
    return profile;
}

namespace {
const std::function<bool()>* frame_function = nullptr;
void one_frame() {
    if (!(*frame_function)()) emscripten_cancel_main_loop();
}
}  // namespace

void run_frames(const std::function<bool()>& frame) {
    frame_function = &frame;
    // 0: at the browser's frame rate; true: never return here, so that the caller's locals, which the frame
    // function refers to, stay alive (emscripten unwinds the stack without destroying them)
    emscripten_set_main_loop(one_frame, 0, true);
}

bool can_start_threads() { return false; }

void publish_state(const std::string& line) {
    static std::string shown;
    if (line == shown) return;
    shown = line;
    EM_ASM({ document.getElementById('state').textContent = UTF8ToString($0); }, line.c_str());
}

}  // namespace hsr::viz
