// SPDX-License-Identifier: MIT
#include "work_frame.h"

#include <SDL.h>
#include <imgui.h>
#include "imgui_backends.h"

#include <array>
#include <cstdio>
#include <string>

#include "panels/work_panel.h"
#include "platform.h"
#include "render/gl.h"
#include "render/palette.h"
#include "scripted_input.h"

namespace hsr::viz {

bool offscreen_driver() {
    const char* driver = SDL_GetCurrentVideoDriver();
    return driver && std::string(driver) == "offscreen";
}

void work_frame(const algo::WorkProgress& p, Window& w, LessonPlay& lp, const AppOptions& o, std::size_t& next_key, bool& quit) {
    if (p.finished) {  // the last word: how long it took, on the terminal
        std::printf("hsrviz: %s\n", p.sentence().c_str());
        std::fflush(stdout);
        return;
    }
    SDL_Event e;
    if (next_key < o.keys.size() && o.keys[next_key] == "Escape" && key_event("Escape", e)) SDL_PushEvent(&e), ++next_key;
    SDL_PumpEvents();
    std::array<SDL_Event, 64> keys_down;
    const int n = SDL_PeepEvents(keys_down.data(), int(keys_down.size()), SDL_PEEKEVENT, SDL_KEYDOWN, SDL_KEYDOWN);
    for (int k = 0; k < n; ++k)
        if (keys_down[std::size_t(k)].key.keysym.sym == SDLK_ESCAPE) lp.stopped_by = "Esc", lp.stop_work = true;
    if (SDL_HasEvent(SDL_QUIT)) lp.stopped_by = "the window closing", lp.stop_work = true, quit = true;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplSDL2_NewFrame();
    ImGui::NewFrame();
    const ImGuiIO& io = ImGui::GetIO();
    glViewport(0, 0, GLsizei(io.DisplaySize.x * io.DisplayFramebufferScale.x), GLsizei(io.DisplaySize.y * io.DisplayFramebufferScale.y));
    glClearColor(palette::background.x, palette::background.y, palette::background.z, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    work_panel(p, io.DisplaySize.x, io.DisplaySize.y);
    publish_state("working: " + p.sentence());
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    SDL_GL_SwapWindow(w.window);
    if (offscreen_driver()) glFinish();
    let_the_frame_show();
}

}  // namespace hsr::viz
