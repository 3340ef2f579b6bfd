// SPDX-License-Identifier: MIT
// The page's entry point: the window with the default lesson, as `hsrviz` with no arguments opens it, or with the
// lesson, step, language and projector scale the page's address names (#lesson=05_bsp_traversal&step=12&lang=de).
// (The command line's subcommands need a terminal and files: the page has neither.)
#include <SDL.h>
#include <emscripten.h>

#include <cstdio>
#include <string>

#include "app.h"
#include "state/lesson.h"
#include "state/place_link.h"

namespace {
// Static, not a local of main: run_app never returns in a browser (web/platform_web.cpp), and main must hold nothing
// that needs destroying around the call. Emscripten then calls run_app directly rather than through a JavaScript
// exception wrapper, and such a wrapper would move the stack pointer back over run_app's locals when the main loop
// starts (by throwing "unwind"). Those locals must stay alive: the frames use them.
hsr::viz::AppOptions options;

// The lesson, step, language and projector scale the page's address names. (Its own function: main must hold no
// local that needs destroying when it calls run_app, see above; nor may this be inlined into it.)
[[gnu::noinline]] void read_address() {
    using namespace hsr::viz;
    std::string problems;
    const PlaceLink link = read_place_link(emscripten_run_script_string("location.hash"), problems);
    if (!problems.empty()) std::fprintf(stderr, "hsrviz: the page's address: %s\n", problems.c_str());  // the console
    options.lesson_path = link.lesson.empty() ? default_lesson_path() : linked_lesson_path(link.lesson);
    options.start_step = link.step;
    if (!link.language.empty()) options.language = link.language;
    options.projector = link.projector;
}
}  // namespace

int main() {
    read_address();
    // The page pauses only where the window asks it to (platform.h let_the_frame_show, in long work). Left to itself,
    // SDL built with Asyncify sleeps at every swap: each frame would unwind out of the browser's animation frame,
    // and the page's script could find the window halfway through a frame.
    SDL_SetHint(SDL_HINT_EMSCRIPTEN_ASYNCIFY, "0");
    // the browser's window, as the desktop window opens at the size it is given
    options.width = EM_ASM_INT({ return window.innerWidth; });
    options.height = EM_ASM_INT({ return window.innerHeight; });
    options.size_given = true;
    return hsr::viz::run_app(options);
}
