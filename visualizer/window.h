// SPDX-License-Identifier: MIT
// The window, its OpenGL 3.3 context and Dear ImGui, opened as the options and the last run's settings say.
#pragma once

#include <SDL.h>
#include <imgui.h>

#include "app.h"
#include "state/window_settings.h"

namespace hsr::viz {

// A window a person works in, not one a command line scripts (screenshots, recordings, GIFs keep their size).
bool interactive(const AppOptions& o);

struct Window {
    SDL_Window* window = nullptr;
    SDL_GLContext gl = nullptr;
    WindowSettings settings;  // as the last run left them

    bool open(const AppOptions& o);  // false (having said why) when there is no window or no OpenGL 3.3
    void close();
};

// Dear ImGui's context, fonts and style (high contrast for a projector) on the window, at initial_scale(o).
void setup_imgui(const Window& w, const AppOptions& o);
// The scale the window starts at: --scale; else 1.3 for a projector, the screen's DPI / 96 on a high-DPI screen
// (144 dpi and more), else 1.
float initial_scale(const AppOptions& o);
// The window's two fonts at `scale` into ImGui's atlas: DejaVu Sans for text, DejaVu Sans Mono for pseudocode,
// with every character a lesson may use (state/glyphs.h); ImGui's own ASCII font when DejaVu is missing.
void load_fonts(ImGuiIO& io, float scale);
// Type, paddings and frames rebuilt at `scale` (Ctrl+= and Ctrl+−). Between frames only.
void apply_scale(float scale);

}  // namespace hsr::viz
