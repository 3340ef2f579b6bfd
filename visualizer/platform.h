// SPDX-License-Identifier: MIT
// What differs between the desktop window and the same window in a browser, in one place: the OpenGL profile and
// its shading language, how frames are driven, whether the window may start threads, and how files reach the person
// and come back (the browser's downloads, file picker and storage; the desktop's disk). The desktop's answers are
// in platform_desktop.cpp; the browser's in web/platform_web.cpp (web/CMakeLists.txt builds that one instead).
#pragma once

#include <cstddef>
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

// What a frame did: drew the window, found nothing to draw (a page skips the frame and shows the last one), or ended
// the run (the window closed, the screenshot written).
enum class Frame { drawn, idle, last };
// Calls frame() until it returns Frame::last. The desktop loops; a browser calls it once per animation frame and
// never returns to the caller (whose locals stay alive: the page runs until it is closed).
void run_frames(const std::function<Frame()>& frame);

// A frame drawn from inside long work (the progress box, five times a second) reaches the screen, and the keys
// pressed meanwhile (Esc stops the work) reach the window. The desktop's swap shows the frame and its event queue
// fills by itself. A browser shows the canvas and hands over key presses only between its tasks: the page pauses
// the work there for an instant (emscripten's Asyncify unwinds the stack and winds it back).
void let_the_frame_show();

// Can the window start a thread (the run-time report's measurement in the background)? A browser page without
// worker threads cannot: the work then runs in the frame that asks for it.
bool can_start_threads();

// The player's state in a line a page's script can read ("step 3 of 64, paused, question open, score 1 of 2"; during
// long work "working: opening huge.toml: 3,274,304 machine steps, 2.7 s"), once a frame: the browser's tests read
// it; the desktop has no use for it.
void publish_state(const std::string& line);

// Where the player stands, as a link names it: the shipped lesson's name ("05_bsp_traversal"; empty for any other
// file) and the step. A browser writes them into the page's address (#lesson=05_bsp_traversal&step=12), so that a
// teacher copies the exact moment; the desktop has no address.
void publish_place(const std::string& lesson, std::size_t step);

// What the page's script may ask the window, answered by `answer`: "trace" (the hash of the events played so far,
// for the test that compares the page with the desktop after the same keys), "lesson" (the file playing), "error"
// (shown instead of it), "language" (the narration's), "practice" (answered and right, over the topics), "type_size"
// (in points), "layout" (the last frame's layout problems) and "window_point X Y" (where the point a --keys gesture
// names is in the window). The desktop has no page to ask.
void answer_queries(std::function<std::string(const std::string& question)> answer);

// A file written to outlive the run (the settings): a browser copies its in-memory files into its own storage
// (IndexedDB); the desktop wrote it to disk already.
void keep_written(const std::string& path);

// A file written for the person (an export, a saved scene): a browser offers it as a download; on the desktop it is
// where the note says.
void offer_download(const std::string& path);

// O: the person asks to open a lesson or scene file of their own. A browser shows its file picker (the chosen files
// arrive as SDL_DROPFILE events, as files dropped on the window do). False where there is no picker: the desktop's
// person drops the file on the window, or names it on the command line.
bool pick_files();

}  // namespace hsr::viz
