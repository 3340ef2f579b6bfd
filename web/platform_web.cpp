// SPDX-License-Identifier: MIT
// The browser's platform (platform.h): WebGL 2 (OpenGL ES 3.0), frames driven by the browser's animation frames, no
// threads (the page is built without workers), the page's address, its downloads, its file picker and its storage.
// The page's side of these is in web/shell.html.
#include <SDL.h>
#include <emscripten.h>

#include <string>

#include "platform.h"
#include "scripted_input.h"

namespace hsr::viz {

const GlProfile& gl_profile() {
    static const GlProfile profile{3, 0, true, "#version 300 es", "precision mediump float;\n", true};
    return profile;
}

namespace {
const std::function<Frame()>* frame_function = nullptr;
void one_frame() {
    const double start = emscripten_get_now();
    const Frame done = (*frame_function)();
    // the page's frame log: how long each drawn frame's work took (not the time between frames, which the display
    // paces; nor the frames skipped while nothing moves)
    if (done == Frame::drawn) EM_ASM({ Module.frame_log.push($0); }, emscripten_get_now() - start);
    if (done == Frame::last) emscripten_cancel_main_loop();
}
std::function<std::string(const std::string&)> query_answer;
bool paused_in_work = false;  // in let_the_frame_show: the window's state is half-way through the work
}  // namespace

void run_frames(const std::function<Frame()>& frame) {
    frame_function = &frame;
    // 0: at the browser's frame rate; true: never return here, so that the caller's locals, which the frame
    // function refers to, stay alive (emscripten unwinds the stack without destroying them)
    emscripten_set_main_loop(one_frame, 0, true);
}

// emscripten_sleep(0): back to the browser's event loop at once (it composites the canvas and runs the key
// handlers, which queue SDL's events), then on with the work where it was
void let_the_frame_show() {
    paused_in_work = true;
    emscripten_sleep(0);
    paused_in_work = false;
}

bool can_start_threads() { return false; }

void publish_state(const std::string& line) {
    static std::string shown;
    if (line == shown) return;
    shown = line;
    EM_ASM({ document.getElementById('state').textContent = UTF8ToString($0); }, line.c_str());
}

void publish_place(const std::string& lesson, std::size_t step) {
    static std::string shown;
    const std::string place = lesson.empty() ? std::string() : "#lesson=" + lesson + "&step=" + std::to_string(step);
    if (place == shown) return;
    shown = place;
    // replaceState: the address follows the player without filling the browser's history with every step
    EM_ASM({ Module.show_place(UTF8ToString($0)); }, place.c_str());
}

void answer_queries(std::function<std::string(const std::string&)> answer) { query_answer = std::move(answer); }

void keep_written(const std::string&) {
    EM_ASM({ Module.keep_files(); });
}

void offer_download(const std::string& path) {
    EM_ASM({ Module.download(UTF8ToString($0)); }, path.c_str());
}

bool pick_files() {
    EM_ASM({ document.getElementById('open-file').click(); });
    return true;
}

}  // namespace hsr::viz

// Called by the page's script (web/shell.html)
extern "C" {

// platform.h answer_queries: "trace" (the hash of the events played so far), "lesson", …; "" to a question the window
// does not know, and "working" to every question while long work is paused for the browser (what the window holds
// is then half-way through being changed).
EMSCRIPTEN_KEEPALIVE const char* hsr_query(const char* question) {
    static std::string answer;
    if (hsr::viz::paused_in_work) return "working";
    answer = hsr::viz::query_answer ? hsr::viz::query_answer(question) : std::string();
    return answer.c_str();
}

// A file the person picked or dropped, already written into the page's file system: it arrives as the desktop's
// dropped files do, as an SDL_DROPFILE event (the window frees the name).
EMSCRIPTEN_KEEPALIVE void hsr_file_arrived(const char* path) { hsr::viz::push_file_drop(path); }

}  // extern "C"
