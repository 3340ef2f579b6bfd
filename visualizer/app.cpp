// SPDX-License-Identifier: MIT
// The window's loop, as a recipe: open the window as the last run left it, load the lesson, then each frame take the
// input (scripted keys first, through the same queue), update the lesson, draw, capture, and remember the settings.
// Each step's own work is in its file: key_input (keys and the mouse), frame_drawing (a frame), frame_capture
// (--record, E, --gif, --screenshot, --frame-log), work_frame (a frame inside long work), page_queries (what the
// page's script asks), remembered_settings, scripted_input.
//
// Family-blind: what a family draws, frames, edits and how it takes gestures is its screen's (screens/), reached
// through LessonPlay::with_family_screen; the lesson's update is lesson_play.cpp's, the window's setup window.cpp's.
#include "app.h"

#include <SDL.h>
#include <imgui.h>
#include "imgui_backends.h"

#include <cstdio>
#include <string>
#include <vector>

#include "frame_capture.h"
#include "frame_drawing.h"
#include "frame_panels.h"
#include "key_input.h"
#include "lesson_play.h"
#include "page_queries.h"
#include "panels/layout_audit.h"
#include "platform.h"
#include "remembered_settings.h"
#include "render/gl.h"
#include "scripted_input.h"
#include "state/place_link.h"
#include "state/strings.h"
#include "window.h"
#include "work_frame.h"

namespace hsr::viz {

int run_app(const AppOptions& o) {
    // Window, GL and ImGui, as the last run left the window
    Window w;
    std::string warning;
    const std::string settings_path = window_settings_path();
    const WindowSettings settings = read_window_settings(settings_path, warning);
    if (!warning.empty()) std::fprintf(stderr, "hsrviz: %s\n", warning.c_str());
    w.settings = settings;
    if (!w.open(o)) {
        w.close();
        return 1;
    }
    setup_imgui(w, o);
    ImGuiIO& io = ImGui::GetIO();

    int exit_code = 0;
    {
        // The lesson, as the options and the settings say
        LessonPlay lp;
        std::size_t next_key = 0;  // of --keys
        bool quit = false;         // the window was closed while long work ran
        lp.show_work = [&](const algo::WorkProgress& p) { work_frame(p, w, lp, o, next_key, quit); };
        lp.side = settings.side;
        lp.practice.restore(settings.practice);
        lp.scale = lp.first_scale = initial_scale(o);
        if (!o.projector && o.scale <= 0 && settings.scale) lp.scale = *settings.scale;  // the size last chosen with Ctrl+±
        lp.load(o);
        float applied_scale = lp.first_scale;  // as the window opened (a remembered size is applied at the first frame)
        if (o.language) lp.classroom.choose_language(*o.language);  // a link's
        else if (!settings.language.empty()) lp.classroom.choose_language(settings.language);  // the language last chosen
        if (o.start_step && lp.session()) lp.session()->seek(*o.start_step);
        WindowSettings saved = settings;  // as the settings file has them now
        std::string linked_path, linked_name;  // the lesson's name in a link, found once per lesson
        lp.playback.playing = o.autoplay;
        lp.animate = !o.screenshot && !o.record_dir && !o.gif;
        lp.questions_hold = !o.record_dir && !o.gif;  // recordings and slides show the whole lesson
        FrameCapture capture;
        bool running = capture.begin(lp, o, exit_code);
        Renderer renderer;
        // the page's script may ask where the player stands (the desktop's page-less platform never asks)
        answer_queries([&lp, &renderer](const std::string& question) { return page_answer(lp, renderer, question); });
        std::uint64_t frame = 0, last_ticks = SDL_GetTicks64();
        bool orbiting = false;
        std::uint64_t awake_until = SDL_GetTicks64() + 1000;  // ms: until when frames are drawn without waiting for input
        const bool offscreen = offscreen_driver();
        run_frames([&] {  // one frame (a browser calls it once per animation frame)
            if (!running || quit) return Frame::last;
            // Input: scripted keys and gestures first (through the same queue), then every event
            UiActions actions;
            bool scripted_shift = false;
            if (frame > 0 && next_key < o.keys.size()) {
                if (!push_scripted_input(o.keys[next_key], lp, renderer, scripted_shift)) {
                    std::fprintf(stderr, "hsrviz: --keys: unknown key or gesture \"%s\"\n", o.keys[next_key].c_str());
                    exit_code = 2;
                    return Frame::last;
                }
                ++next_key;
            }
            // Asleep while nothing moves: a paused window waits for input (waking twice a second for edited files)
            // instead of drawing the same frame again; it draws on for a moment after any input, for tweens to end
            // (and while a note shows, so that it fades and goes). A page cannot wait inside a frame (the browser's
            // events arrive between frames; SDL would spin): it skips the frame, and the canvas keeps the last one.
            const bool note_showing = lp.toasts.until() > seconds_now();
            const bool asleep = interactive(o) && !lp.playback.playing && !note_showing && !lp.measuring.running() &&
                                SDL_GetTicks64() > awake_until;
            const bool in_browser = gl_profile().browser_paced;
            if (asleep && !in_browser) SDL_WaitEventTimeout(nullptr, 500);
            SDL_Event e;
            std::vector<std::string> dropped;  // files dropped on the window (or picked in a browser) together
            while (SDL_PollEvent(&e)) {
                awake_until = SDL_GetTicks64() + 1000;
                ImGui_ImplSDL2_ProcessEvent(&e);
                if (e.type == SDL_QUIT) running = false;
                if (e.type == SDL_DROPFILE) dropped.emplace_back(e.drop.file), SDL_free(e.drop.file);
                if (!io.WantCaptureKeyboard) actions_of_key(e, actions);
                if (const auto p = pointer_of(e, io.WantCaptureMouse)) {  // the family's gestures, else orbit the 3D view
                    const ViewGeometry g = geometry_now(lp, renderer);
                    const bool taken = lp.family && lp.with_family_screen([&](auto& s, auto& screen) { return screen.pointer(s, *p, g, actions); });
                    if (p->kind == Pointer::Kind::press && !p->right) orbiting = !taken && !p->over_ui;
                    if (p->kind == Pointer::Kind::release) orbiting = false;
                    if (p->kind == Pointer::Kind::move && orbiting) lp.camera.orbit(float(e.motion.xrel), float(e.motion.yrel));
                }
                if (e.type == SDL_MOUSEWHEEL && !io.WantCaptureMouse) lp.camera.zoom(float(e.wheel.y));
            }
            if (scripted_shift) SDL_SetModState(KMOD_NONE);
            if (asleep && in_browser && SDL_GetTicks64() > awake_until) return Frame::idle;  // no input came: nothing to draw
            if (!dropped.empty()) actions.open_lesson = file_to_open(dropped);
            if (actions.open_file && !pick_files())
                lp.tell("to open a lesson or scene file of your own, drop it on the window", tr("notes.drop_to_open"));

            // The window's title names the lesson playing (a teacher switching lessons sees which one is up)
            const std::string title = lp.session() ? "hsrviz — " + lp.session()->lesson().title : "hsrviz";
            if (title != SDL_GetWindowTitle(w.window)) SDL_SetWindowTitle(w.window, title.c_str());

            // Update: recording and screenshots take one Step per frame, so the same command gives the same picture
            const std::uint64_t ticks = SDL_GetTicks64();
            // (a screenshot's frames after the last step only settle the panels: ImGui shows a scrollbar a frame
            // after the content outgrew its box, and a step then would outgrow it again)
            const bool screenshot_steps = o.screenshot && o.keys.empty() && frame < std::uint64_t(o.frames);
            if ((o.record_dir || o.gif || screenshot_steps) && frame > 0) actions.step = true;
            lp.update(actions, double(ticks - last_ticks) / 1000.0, o);
            last_ticks = ticks;

            // Draw
            if (lp.scale != applied_scale) apply_scale(applied_scale = lp.scale);  // fonts are rebuilt between frames
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplSDL2_NewFrame();
            ImGui::NewFrame();
            layout_problems().clear(), result_scrolls() = false, scrolling_boxes().clear();
            int width = 0, height = 0;
            SDL_GL_GetDrawableSize(w.window, &width, &height);
            UiActions from_panels;
            draw_frame(lp, renderer, arrange_frame(lp, io.DisplaySize.x, io.DisplaySize.y), io.DisplayFramebufferScale.x, from_panels);
            ImGui::Render();
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            ++frame;

            // Capture: --record, E, --gif, --screenshot
            const bool keys_pressed = next_key >= o.keys.size() && !lp.measuring.running();  // the last one drawn already
            capture.after_draw(lp, o, frame, width, height, keys_pressed, running, exit_code);
            SDL_GL_SwapWindow(w.window);
            // The offscreen driver has no display to wait for: without this, llvmpipe queues every frame's work
            // (2,000 frames held 1.8 GB) and the screenshot's read-back waits for all of it.
            if (offscreen) glFinish();
            capture.after_swap(o);
            // Carry out the panels' requests (buttons, an answer clicked, the depth format, the 3D checkbox, a dragged eye)
            lp.update(from_panels, 0, o);
            publish_state(player_state(lp) + (lp.session() && lp.classroom.questions() > 0
                                                  ? ", score " + std::to_string(lp.classroom.right()) + " of " + std::to_string(lp.classroom.answered())
                                                  : ""));
            if (lp.path != linked_path) linked_name = linked_lesson_name(linked_path = lp.path);
            if (lp.session()) publish_place(linked_name, lp.session()->cursor());
            // what the window remembers is written as it changes (a page is closed, never quit: it has no "at exit")
            remember(settings_path, saved, settings_now(saved, lp, w, o, false));
            return running && !quit ? Frame::drawn : Frame::last;
        });

        capture.finish(lp, o, frame, exit_code);

        // Remember the layout, and now the window's size and place too
        remember(settings_path, saved, settings_now(saved, lp, w, o, true));
        answer_queries({});
    }

    // Cleanup
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplSDL2_Shutdown();
    ImGui::DestroyContext();
    w.close();
    return exit_code;
}

}  // namespace hsr::viz
