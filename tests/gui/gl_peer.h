// SPDX-License-Identifier: MIT
// Our z-buffer and OpenGL's rasteriser (Mesa's llvmpipe here) on the same clip-space triangles, each drawn in a
// colour that encodes its index, with GL_LESS on a 24-bit depth buffer: the visible triangle per pixel from both,
// and the time each took. Shared by gl_raster_check (a test) and zbuffer_vs_llvmpipe (a benchmark).
#pragma once

#include <SDL.h>

#include <vector>

#include <glm/vec4.hpp>

namespace hsr::test {

struct Triangle {
    glm::dvec4 v[3];  // clip space
};

// A hidden window with an OpenGL 3.3 core context (SDL's offscreen driver gives EGL on llvmpipe). Null on failure.
struct GlContext {
    SDL_Window* window = nullptr;
    SDL_GLContext context = nullptr;
    GlContext(int width, int height);
    ~GlContext();
    const char* renderer() const;
};

// Index + 1 per pixel (0 for background), rows top first. `draw_ms`, when given, receives the median of `repeats`
// clears and draws finished with glFinish (the triangles already uploaded; reading back not counted).
std::vector<int> gl_ids(const std::vector<Triangle>& tris, int width, int height, double* draw_ms = nullptr, int repeats = 1);
// The same from our z-buffer machine drained with polygon-level events; `fill_ms` times projection (project_polygons) and fill.
std::vector<int> our_ids(const std::vector<Triangle>& tris, int width, int height, double* fill_ms = nullptr, int repeats = 1);

}  // namespace hsr::test
