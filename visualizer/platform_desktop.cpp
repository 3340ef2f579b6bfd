// SPDX-License-Identifier: MIT
// The desktop's platform: OpenGL 3.3 core, a plain loop, threads.
#include "platform.h"

namespace hsr::viz {

const GlProfile& gl_profile() {
    static const GlProfile profile{3, 3, false, "#version 330 core", ""};
    return profile;
}

void run_frames(const std::function<Frame()>& frame) {
    while (frame() != Frame::last) {
    }
}

void let_the_frame_show() {}

bool can_start_threads() { return true; }

void publish_state(const std::string&) {}
void publish_place(const std::string&, std::size_t) {}
void answer_queries(std::function<std::string(const std::string&)>) {}
void keep_written(const std::string&) {}
void offer_download(const std::string&) {}
bool pick_files() { return false; }

}  // namespace hsr::viz
