// SPDX-License-Identifier: MIT
// The page's entry point: the window with the default lesson, as `hsrviz` with no arguments opens it. (The command
// line's subcommands need a terminal and files: the page has neither.)
#include <emscripten.h>

#include "app.h"
#include "state/lesson.h"

namespace {
// Static, not a local of main: run_app never returns in a browser (web/platform_web.cpp), and main must hold nothing
// that needs destroying around the call. Emscripten then calls run_app directly rather than through a JavaScript
// exception wrapper, and such a wrapper would move the stack pointer back over run_app's locals when the main loop
// starts (by throwing "unwind"). Those locals must stay alive: the frames use them.
hsr::viz::AppOptions options;
}  // namespace

int main() {
    options.lesson_path = hsr::viz::default_lesson_path();
    // the browser's window, as the desktop window opens at the size it is given
    options.width = EM_ASM_INT({ return window.innerWidth; });
    options.height = EM_ASM_INT({ return window.innerHeight; });
    options.size_given = true;
    return hsr::viz::run_app(options);
}
