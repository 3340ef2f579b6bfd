// SPDX-License-Identifier: MIT
#include "scripted_input.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <utility>
#include <vector>

#include "frame_drawing.h"
#include "lesson_play.h"

namespace hsr::viz {
namespace {

// "X1:Y1:X2:Y2" → numbers; false unless exactly `count` numbers, each read whole and a place a window can have
// (window points within ±100000: never NaN, inf or a point no mouse reaches).
bool numbers(const std::string& text, std::size_t count, std::vector<double>& out) {
    std::stringstream in(text);
    std::string part;
    while (std::getline(in, part, ':')) {
        char* end = nullptr;
        const double v = std::strtod(part.c_str(), &end);
        if (part.empty() || *end != '\0' || !(std::abs(v) <= 1e5)) return false;
        out.push_back(v);
    }
    return out.size() == count;
}

}  // namespace

std::optional<ScriptedInput> parse_scripted_input(const std::string& token) {
    struct Gesture {
        const char* prefix;
        ScriptedInput::Kind kind;
        std::size_t count;
    };
    for (const Gesture& g : {Gesture{"Drag:", ScriptedInput::Kind::drag, 4}, Gesture{"ShiftDrag:", ScriptedInput::Kind::shift_drag, 4},
                             Gesture{"RightClick:", ScriptedInput::Kind::right_click, 2}}) {
        const std::string p(g.prefix);
        const auto kind = g.kind;
        const std::size_t count = g.count;
        if (token.rfind(p, 0) != 0) continue;
        std::vector<double> v;
        if (!numbers(token.substr(p.size()), count, v)) return std::nullopt;
        ScriptedInput s{kind, "", {v[0], v[1]}, count == 4 ? glm::dvec2(v[2], v[3]) : glm::dvec2(v[0], v[1]), {}};
        return s;
    }
    if (token.rfind("Drop:", 0) == 0) {
        ScriptedInput s{ScriptedInput::Kind::drop, "", {}, {}, {}};
        std::stringstream in(token.substr(5));
        for (std::string file; std::getline(in, file, ';');)
            if (!file.empty()) s.files.push_back(file);
        if (s.files.empty()) return std::nullopt;
        return s;
    }
    SDL_Event e;
    if (!key_event(token, e)) return std::nullopt;
    return ScriptedInput{ScriptedInput::Kind::key, token, {}, {}, {}};
}

bool key_event(const std::string& name, SDL_Event& e) {
    // modifiers first, in any order: Shift+Right, Ctrl+=, Ctrl+Shift+Z
    std::string key = name;
    Uint16 mod = KMOD_NONE;
    for (bool more = true; more;) {
        more = false;
        for (const auto& [prefix, bit] : {std::pair<const char*, Uint16>{"Shift+", KMOD_LSHIFT}, {"Ctrl+", KMOD_LCTRL}})
            if (key.size() > std::strlen(prefix) && key.rfind(prefix, 0) == 0) key = key.substr(std::strlen(prefix)), mod |= bit, more = true;
    }
    const SDL_Keycode code = SDL_GetKeyFromName(key.c_str());
    if (code == SDLK_UNKNOWN) return false;
    e = SDL_Event{};
    e.type = SDL_KEYDOWN;
    e.key.state = SDL_PRESSED;
    e.key.keysym.sym = code;
    e.key.keysym.scancode = SDL_GetScancodeFromKey(code);
    e.key.keysym.mod = mod;
    return true;
}

SDL_Event mouse_button_event(bool down, Uint8 button, int x, int y) {
    SDL_Event e{};
    e.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
    e.button.button = button;
    e.button.state = down ? SDL_PRESSED : SDL_RELEASED;
    e.button.clicks = 1;
    e.button.x = x, e.button.y = y;
    return e;
}

SDL_Event mouse_motion_event(int x, int y, int dx, int dy, bool left_held) {
    SDL_Event e{};
    e.type = SDL_MOUSEMOTION;
    e.motion.x = x, e.motion.y = y, e.motion.xrel = dx, e.motion.yrel = dy;
    e.motion.state = left_held ? SDL_BUTTON_LMASK : 0;
    return e;
}

void push_file_drop(const std::string& path) {
    SDL_Event e{};
    e.type = SDL_DROPFILE;
    e.drop.file = SDL_strdup(path.c_str());
    if (SDL_PushEvent(&e) != 1) SDL_free(e.drop.file);
}

bool push_scripted_input(const std::string& text, LessonPlay& lp, const Renderer& r, bool& shift_held) {
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

}  // namespace hsr::viz
