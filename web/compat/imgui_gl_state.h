// SPDX-License-Identifier: MIT
// Included before Dear ImGui's OpenGL 3 backend in the page only (web/dependencies.cmake). The backend saves about
// fifteen GL states before it draws and restores them after. In a browser each glGetIntegerv is a getParameter that
// waits for the GPU process to finish the work already queued: 80 % of a frame in Chromium with SwiftShader. The
// window leaves known state before ImGui draws (web/imgui_gl_state.cpp says which), so the backend is told that.
#pragma once
#ifdef __cplusplus
extern "C" {
#endif
void hsr_imgui_get_integerv(unsigned int pname, int* data);
unsigned char hsr_imgui_is_enabled(unsigned int capability);
#ifdef __cplusplus
}
#endif
#define glGetIntegerv hsr_imgui_get_integerv
#define glIsEnabled hsr_imgui_is_enabled
