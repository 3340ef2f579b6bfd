// SPDX-License-Identifier: MIT
// Dear ImGui's SDL2 and OpenGL 3 backends. The SDL2 one's header was renamed in ImGui 1.88 (imgui_impl_sdl.h →
// imgui_impl_sdl2.h): Debian 12 has ImGui 1.86, Debian 13 has 1.90, and CMake finds which one is installed.
#pragma once
#include <imgui_impl_opengl3.h>
#ifdef HSR_IMGUI_SDL2_HEADER
#include <imgui_impl_sdl2.h>
#else
#include <imgui_impl_sdl.h>
#endif
