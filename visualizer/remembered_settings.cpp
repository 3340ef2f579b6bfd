// SPDX-License-Identifier: MIT
#include "remembered_settings.h"

#include <SDL.h>

#include <cstdio>

#include "scene/input_file.h"
#include "platform.h"

namespace hsr::viz {

WindowSettings settings_now(const WindowSettings& before, const LessonPlay& lp, const Window& w, const AppOptions& o, bool with_place) {
    WindowSettings keep = before;
    keep.side = lp.side;
    keep.language = lp.classroom.chosen_language();
    keep.practice = lp.practice.records();
    // the type's size chosen with Ctrl+± (Ctrl+0, back to the screen's, forgets it); a projector's and --scale's are their own
    if (!o.projector && o.scale <= 0) keep.scale = lp.scale != lp.first_scale ? std::optional<float>(lp.scale) : std::nullopt;
    if (with_place && interactive(o) && !o.projector) {
        const Uint32 flags = SDL_GetWindowFlags(w.window);
        keep.maximized = (flags & SDL_WINDOW_MAXIMIZED) != 0;
        if (!keep.maximized && !(flags & SDL_WINDOW_FULLSCREEN)) {
            int x = 0, y = 0;
            SDL_GetWindowSize(w.window, &keep.width, &keep.height);
            SDL_GetWindowPosition(w.window, &x, &y);
            keep.x = x, keep.y = y;
        }
    }
    return keep;
}

void remember(const std::string& path, WindowSettings& saved, const WindowSettings& now) {
    if (now == saved) return;
    if (const std::string why = write_window_settings(path, now); !why.empty())
        std::fprintf(stderr, "hsrviz: the window's settings were not saved: %s\n", algo::printable(why).c_str());
    else keep_written(path);
    saved = now;  // (a failed write is said once, not every frame)
}

}  // namespace hsr::viz
