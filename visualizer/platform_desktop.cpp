// SPDX-License-Identifier: MIT
// The desktop's platform: OpenGL 3.3 core, a plain loop, threads.
#include "platform.h"

namespace hsr::viz {

const GlProfile& gl_profile() {
    static const GlProfile profile{3, 3, false, "#version 330 core", ""};
    return profile;
}

void run_frames(const std::function<bool()>& frame) {
    while (frame()) {
    }
}

bool can_start_threads() { return true; }

void publish_state(const std::string&) {}

}  // namespace hsr::viz
