// SPDX-License-Identifier: MIT
// [SECTION] input: keys and the mouse
// [SECTION] drawing a frame (draw)
// [SECTION] the loop
//
// Family-blind: what a family draws, frames, edits and how it takes gestures is its screen's (screens/), reached
// through Lessonplay::with_family_screen; the lesson's update is lesson_play.cpp's, the window's setup window.cpp's.
#include "app.h"

#include <SDL.h>
#include <imgui.h>
#include "imgui_backends.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "capture.h"
#include "state/output_folder.h"
#include "state/place_link.h"
#include "state/trace.h"
#include "state/strings.h"
#include "frame_panels.h"
#include "gif_writer.h"
#include "lesson_play.h"
#include "platform.h"
#include "panels/layout_audit.h"
#include "panels/work_panel.h"
#include "render/gl.h"
#include "render/palette.h"
#include "scene/input_file.h"
#include "scripted_input.h"
#include "window.h"

namespace hsr::viz {
namespace {

// ── [SECTION] input: keys and the mouse ─────────────────────────────────────────────────────────────────────
void keys(const SDL_Event& e, UiActions& a) {
    if (e.type != SDL_KEYDOWN) return;
    const bool shift = (e.key.keysym.mod & KMOD_SHIFT) != 0;
    switch (e.key.keysym.sym) {
        case SDLK_SPACE: a.toggle_play = true; break;
        case SDLK_RIGHT: (shift ? a.micro_step : a.step) = true, a.left = -1; break;
        case SDLK_LEFT: (shift ? a.micro_step_back : a.step_back) = true, a.left = +1; break;
        case SDLK_HOME: a.to_start = true; break;
        case SDLK_END: a.to_end = true; break;
        case SDLK_F5: a.reload = true; break;
        case SDLK_F1: a.toggle_keys = true; break;
        case SDLK_e: a.export_all = true; break;
        case SDLK_z:
            if (e.key.keysym.mod & KMOD_CTRL) (shift ? a.redo : a.undo) = true;
            break;
        case SDLK_y: if (e.key.keysym.mod & KMOD_CTRL) a.redo = true; break;
        case SDLK_s: a.save_scene = true; break;
        case SDLK_ESCAPE: a.close_overlays = true; break;
        case SDLK_PAGEDOWN: a.next_chapter = true; break;
        case SDLK_PAGEUP: a.previous_chapter = true; break;
        case SDLK_l: a.next_language = true; break;
        case SDLK_p: a.toggle_presets = true; break;
        case SDLK_r: a.toggle_report = true; break;
        case SDLK_LEFTBRACKET: a.column_narrower = true; break;
        case SDLK_RIGHTBRACKET: a.column_wider = true; break;
        case SDLK_b: a.back_to_lesson = true; break;
        case SDLK_v: a.toggle_3d = true; break;  // the family's other view: z-buffer 3D, portals walk-through, culling camera
        case SDLK_n: a.next_lesson = shift ? -1 : 1; break;  // the next (previous) lesson of the course
        case SDLK_m: a.toggle_menu = true; break;
        case SDLK_o: a.open_file = true; break;
        case SDLK_x: a.toggle_practice = true; break;
        case SDLK_w: a.toggle_walk = true; break;  // culling and portal lessons: walk through the scene
        case SDLK_PERIOD:
        case SDLK_KP_PERIOD: a.typed = '.'; break;
        case SDLK_COMMA: a.typed = ','; break;
        case SDLK_BACKSPACE: a.typed = '\b'; break;
        case SDLK_UP: a.up_down = -1, a.forward = +1; break;
        case SDLK_DOWN: a.up_down = +1, a.forward = -1; break;
        case SDLK_RETURN:
        case SDLK_KP_ENTER: a.enter = true; break;
        case SDLK_EQUALS:
        case SDLK_PLUS:
        case SDLK_KP_PLUS:
            if (e.key.keysym.mod & KMOD_CTRL) a.scale_step = +1;
            break;
        case SDLK_MINUS:
        case SDLK_KP_MINUS:
            if (e.key.keysym.mod & KMOD_CTRL) a.scale_step = -1;
            else a.typed = '-';  // a practice answer's sign
            break;
        case SDLK_0:
            if (e.key.keysym.mod & KMOD_CTRL) a.scale_reset = true;
            else a.digit = 0;
            break;
        default:  // 1 … 9: a question's choice (or a preset while the presets show)
            if (e.key.keysym.sym >= SDLK_1 && e.key.keysym.sym <= SDLK_9) a.digit = int(e.key.keysym.sym - SDLK_0);
            break;
    }
}

// A mouse button or motion event as a screen's gesture input.
std::optional<Pointer> pointer_of(const SDL_Event& e, bool over_ui) {
    const bool shift = (SDL_GetModState() & KMOD_SHIFT) != 0;
    switch (e.type) {
        case SDL_MOUSEBUTTONDOWN:
        case SDL_MOUSEBUTTONUP:
            if (e.button.button != SDL_BUTTON_LEFT && e.button.button != SDL_BUTTON_RIGHT) return std::nullopt;
            return Pointer{.kind = e.type == SDL_MOUSEBUTTONDOWN ? Pointer::Kind::press : Pointer::Kind::release,
                           .right = e.button.button == SDL_BUTTON_RIGHT, .shift = shift, .over_ui = over_ui,
                           .x = float(e.button.x), .y = float(e.button.y)};
        case SDL_MOUSEMOTION:
            return Pointer{.kind = Pointer::Kind::move, .shift = shift, .over_ui = over_ui, .x = float(e.motion.x), .y = float(e.motion.y)};
        default: return std::nullopt;
    }
}

// ── [SECTION] drawing a frame (draw) ────────────────────────────────────────────────────────────────────────
struct Renderer {
    LineBatches batches;
    std::vector<Label> labels;
    ViewGeometry geometry;  // of the last frame's 3D view, for picking
};

// The 3D view as the last frame drew it, with the overlays and the second view as they are now.
ViewGeometry geometry_now(const Lessonplay& lp, const Renderer& r) {
    ViewGeometry g = r.geometry;
    g.overlay_open = lp.show_presets || lp.show_keys || lp.show_report || lp.show_menu;
    g.second_view = lp.second_view;
    return g;
}

// `layout` is in ImGui's units (window points); `scale` turns them into framebuffer pixels (2 on a HiDPI display).
void draw_frame(Lessonplay& lp, Renderer& r, const PanelLayout& layout, float scale, UiActions& actions) {
    const float view_w = layout.width - layout.side, view_h = layout.height - layout.bottom;
    const auto px = [&](float points) { return GLsizei(points * scale); };
    glViewport(0, 0, px(layout.width), px(layout.height));
    glClearColor(palette::background.x, palette::background.y, palette::background.z, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const glm::mat4 vp = draw_frame_content(lp, r.batches, r.labels, layout, actions);  // ImGui's part, drawn later
    if (!lp.session()) return;
    glViewport(0, px(layout.bottom), px(view_w), px(view_h));  // GL's y axis points up
    r.geometry.view_projection = vp, r.geometry.width = view_w, r.geometry.height = view_h;
    const float thick = scale * lp.scale;  // lines and points grow with the type (projector, Ctrl+=)
    const glm::vec2 viewport(float(px(view_w)), float(px(view_h)));
    r.batches.faint.draw(vp, viewport, 1.5f * thick, 7.0f * thick);
    r.batches.bold.draw(vp, viewport, 3.5f * thick, 11.0f * thick);
    glViewport(0, 0, px(layout.width), px(layout.height));
}

// SDL's offscreen driver: no display paces the frames (the window finishes each frame's GL work itself).
bool offscreen_driver() {
    const char* driver = SDL_GetCurrentVideoDriver();
    return driver && std::string(driver) == "offscreen";
}

// A frame drawn from inside long work (the meter's teller, five times a second once it has lasted 0.3 s): the
// progress box over an empty view. The input is only looked at, not taken: Esc stops the work, closing the window
// stops it and quits, and every event stays queued for the frame after the work (a key pressed meanwhile is not
// lost; a scripted Escape is pressed now, as a teacher's would be, the other scripted keys wait for their frames).
void work_frame(const algo::WorkProgress& p, Window& w, Lessonplay& lp, const AppOptions& o, std::size_t& next_key, bool& quit) {
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

// Where the player stands, as the screenshot's line and the page's state line say it: "step 3 of 64, paused,
// question open" (empty when no lesson loaded).
std::string player_state(const Lessonplay& lp) {
    const Session* s = lp.session();
    if (!s) return {};
    return "step " + std::to_string(s->cursor()) + " of " + std::to_string(s->known()) + (s->complete() ? "" : "+") + ", " +
           (lp.playback.playing ? "playing" : "paused") + (lp.classroom.open_question(*s) ? ", question open" : "") +
           (lp.show_menu ? ", lesson menu open" : s->complete() && s->cursor() >= s->known() ? ", end of the lesson" : "");
}

// Where a gesture's point is in the window: a gesture names points as its family's view does (the fat pixels take
// grid pixels, the others the plane z = 0).
glm::vec2 gesture_window_point(Lessonplay& lp, const Renderer& r, glm::dvec2 p) {
    const ViewGeometry g = geometry_now(lp, r);
    if (!lp.family) return g.to_window({p, 0.0});
    return lp.with_family_screen([&](auto& s, auto& screen) { return screen.gesture_point(s, p, g); });
}

// What the page's script asks (platform.h answer_queries): the file playing, the error shown instead of it, the
// narration's language, the practice score over every topic, the played trace, the type's size in points, the last
// frame's layout problems, where a gesture's point is in the window ("window_point X Y": "x y", as --keys' gestures
// name points); "" to anything else.
std::string page_answer(Lessonplay& lp, const Renderer& r, const std::string& question) {
    if (question == "lesson") return lp.path;
    if (question == "error") return lp.error;
    if (question == "language") return lp.classroom.language();
    if (question == "practice") {
        int answered = 0, right = 0;
        for (const auto& [topic, record] : lp.practice.records()) answered += record.answered, right += record.right;
        return "answered " + std::to_string(answered) + ", right " + std::to_string(right);
    }
    if (question == "trace" && lp.session()) return played_trace_text(*lp.session());
    if (question == "type_size") return std::to_string(std::lround(ImGui::GetFontSize()));  // in points
    if (question == "layout") {  // what the last frame's layout audit found (a text cut, a box too small); "" if nothing
        std::string found;
        for (const std::string& problem : layout_problems()) found += (found.empty() ? "" : "; ") + problem;
        return found;
    }
    std::istringstream asked(question);
    std::string word;
    glm::dvec2 p;
    if (asked >> word >> p.x >> p.y && word == "window_point" && std::isfinite(p.x) && std::isfinite(p.y)) {
        const glm::vec2 w = gesture_window_point(lp, r, p);
        return std::to_string(std::lround(w.x)) + " " + std::to_string(std::lround(w.y));
    }
    return "";
}

// What the window remembers now: the column, the language, the practice scores and the type's size always; the
// window's size and place (`with_place`) at the end of a run a person sized it in.
WindowSettings settings_now(const WindowSettings& before, const Lessonplay& lp, const Window& w, const AppOptions& o, bool with_place) {
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

// --keys: the next scripted key or gesture, pushed through SDL's queue as a person's would be. False: unknown.
bool push_scripted_input(const std::string& text, Lessonplay& lp, const Renderer& r, bool& shift_held) {
    const auto input = parse_scripted_input(text);
    if (!input) return false;
    SDL_Event e;
    if (input->kind == ScriptedInput::Kind::key) {
        key_event(input->key, e);
        SDL_PushEvent(&e);
        return true;
    }
    if (input->kind == ScriptedInput::Kind::drop) {
        for (const std::string& file : input->files) push_file_drop(file);
        return true;
    }
    const glm::vec2 a = gesture_window_point(lp, r, input->from), b = gesture_window_point(lp, r, input->to);
    const auto ax = int(std::lround(a.x)), ay = int(std::lround(a.y)), bx = int(std::lround(b.x)), by = int(std::lround(b.y));
    const bool right = input->kind == ScriptedInput::Kind::right_click;
    const Uint8 button = right ? SDL_BUTTON_RIGHT : SDL_BUTTON_LEFT;
    shift_held = input->kind == ScriptedInput::Kind::shift_drag;
    if (shift_held) SDL_SetModState(KMOD_LSHIFT);
    for (SDL_Event m : {mouse_motion_event(ax, ay, 0, 0, false), mouse_button_event(true, button, ax, ay),
                        mouse_motion_event(bx, by, bx - ax, by - ay, !right), mouse_button_event(false, button, bx, by)})
        SDL_PushEvent(&m);
    return true;
}

}  // namespace

// ── [SECTION] the loop ──────────────────────────────────────────────────────────────────────────────────────
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
        Lessonplay lp;
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
        std::optional<GifWriter> gif;  // half the drawable's size (made at the first frame): enough for slides
        bool gif_failed = false;
        bool running = true;
        if (o.gif && lp.session()) {
            lp.session()->seek(o.gif_from);
            if (lp.session()->cursor() < o.gif_from) {  // a GIF of one frame, the last, would not be what was asked
                std::fprintf(stderr, "hsrviz: --from %zu is past the lesson's last step (%zu); the GIF would have no steps\n",
                             o.gif_from, lp.session()->cursor());
                exit_code = 2, running = false;
            }
        }
        const bool record_folder_made = !o.record_dir || make_folder(*o.record_dir);
        if (!record_folder_made) exit_code = 1, running = false;  // said why
        Renderer renderer;
        // the page's script may ask where the player stands (the desktop's page-less platform never asks)
        answer_queries([&lp, &renderer](const std::string& question) { return page_answer(lp, renderer, question); });
        std::uint64_t frame = 0, last_ticks = SDL_GetTicks64();
        bool orbiting = false;
        std::uint64_t awake_until = SDL_GetTicks64() + 1000;  // ms: until when frames are drawn without waiting for input
        std::vector<double> frame_ms;  // --frame-log
        std::uint64_t frame_start = SDL_GetPerformanceCounter();
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
                if (!io.WantCaptureKeyboard) keys(e, actions);
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
            if (o.record_dir) {
                char name[64];
                std::snprintf(name, sizeof name, "/frame_%04llu.png", static_cast<unsigned long long>(frame - 1));
                write_png(*o.record_dir + name, width, height);
                if (!lp.session() || lp.session()->at_end() || frame >= 2000) running = false;
            }
            if (lp.export_pending && lp.session()) {
                lp.export_pending = false;
                std::vector<std::string> written;
                const auto edited = lp.with_family_screen([](const auto& s, const auto& screen) { return screen.edited_scene(s); });
                lp.tell(export_lesson(*lp.session(), lp.path, lp.algorithm, edited, width, height, written));
                for (const std::string& file : written) offer_download(file);
            }
            if (o.gif) {
                if (!gif && !gif_failed) {
                    gif.emplace(*o.gif, o.gif_half ? width / 2 : width, o.gif_half ? height / 2 : height, 50);
                    if (!gif->ok()) std::fprintf(stderr, "hsrviz: cannot write %s\n", o.gif->c_str()), gif.reset(), gif_failed = true, exit_code = 1;
                }
                if (gif) gif->add_frame(frame_pixels(width, height, o.gif_half));
                if (!gif || !lp.session() || lp.session()->at_end() || lp.session()->cursor() >= o.gif_to) running = false;
            }
            // the screenshot waits for every scripted key to be pressed and for R's measurement to be in, then (a few
            // frames at most) for the panel column to settle
            const bool keys_pressed = next_key >= o.keys.size() && !lp.measuring.running();  // the last one drawn already
            const std::uint64_t ready = std::max<std::uint64_t>(std::uint64_t(o.frames), o.keys.size());
            const bool settled = !lp.column.moved() && layout_problems().empty();
            if (o.screenshot && keys_pressed && frame >= ready && (settled || frame >= ready + 8)) {
                if (lp.session()) {
                    std::printf("hsrviz: at %s\n", player_state(lp).c_str());
                    std::printf("hsrviz: played trace %s\n", played_trace_text(*lp.session()).c_str());
                }
                if (lp.session() && lp.classroom.questions() > 0)
                    std::printf("hsrviz: score %d of %d answered, %d questions, language %s\n", lp.classroom.right(),
                                lp.classroom.answered(), lp.classroom.questions(), lp.classroom.language().c_str());
                std::printf("hsrviz: window words %s, narration %s\n", window_strings().language().c_str(), lp.classroom.language().c_str());
                for (const std::string& problem : layout_problems()) std::printf("hsrviz: layout: %s\n", problem.c_str());
                for (const std::string& box : scrolling_boxes()) std::printf("hsrviz: scrolls: %s\n", box.c_str());
                if (result_scrolls() && lp.session() && lp.session()->complete() && lp.session()->cursor() >= lp.session()->known())
                    std::printf("hsrviz: result scrolls: the lesson's state box scrolls at the end of the lesson\n");
                for (const Toasts::Showing& n : lp.toasts.showing(seconds_now())) std::printf("hsrviz: note showing: %s\n", n.text.c_str());
                if (!write_png(*o.screenshot, width, height)) {
                    std::fprintf(stderr, "hsrviz: cannot write %s\n", o.screenshot->c_str());
                    exit_code = 1;
                }
                if (!lp.session()) exit_code = 1;  // the picture shows the error; the exit says the lesson did not load
                running = false;
            }
            SDL_GL_SwapWindow(w.window);
            // The offscreen driver has no display to wait for: without this, llvmpipe queues every frame's work
            // (2,000 frames held 1.8 GB) and the screenshot's read-back waits for all of it.
            if (offscreen) glFinish();
            if (o.frame_log) {  // from the start of one frame to the start of the next
                const std::uint64_t now = SDL_GetPerformanceCounter();
                frame_ms.push_back(1000.0 * double(now - frame_start) / double(SDL_GetPerformanceFrequency()));
                frame_start = now;
            }
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

        // What the run wrote
        if (o.frame_log && !frame_ms.empty()) {
            std::ofstream log(*o.frame_log);
            for (double ms : frame_ms) log << ms << '\n';
            if (!log.flush()) std::fprintf(stderr, "hsrviz: cannot write %s\n", o.frame_log->c_str()), exit_code = 1;
            std::vector<double> sorted = frame_ms;
            std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
            std::printf("hsrviz: %zu frames, median %.2f ms, written to %s\n", frame_ms.size(), sorted[sorted.size() / 2], o.frame_log->c_str());
        }
        if (gif) {
            const int frames = gif->frames();
            if (!gif->close()) exit_code = 1;
            std::printf("hsrviz: wrote %d frames to %s\n", frames, o.gif->c_str());
        }
        if (o.gif && !lp.session()) exit_code = 1;
        if (o.record_dir && record_folder_made) {
            std::printf("hsrviz: wrote %llu frames to %s/frame_*.png\n", static_cast<unsigned long long>(frame), o.record_dir->c_str());
            if (!lp.session()) exit_code = 1;
        }

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
