// SPDX-License-Identifier: MIT
#include "key_input.h"

namespace hsr::viz {

void actions_of_key(const SDL_Event& e, UiActions& a) {
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

}  // namespace hsr::viz
