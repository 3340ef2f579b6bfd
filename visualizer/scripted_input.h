// SPDX-License-Identifier: MIT
// Scripted input for --keys: key presses, and mouse gestures on the 2D view given in world coordinates (the window
// turns them into window points through the view it draws, then into SDL events in the same queue as real ones).
//   Space  Right  Shift+Left  Home  End  F5  S  …   a key press (SDL's key names)
//   Drag:X1:Y1:X2:Y2        left button down at (X1, Y1), moved to (X2, Y2), released: moves an end or the eye
//   ShiftDrag:X1:Y1:X2:Y2   the same with Shift held: draws a new segment in a 2D scene
//   RightClick:X:Y          right button at (X, Y): deletes the segment there in a 2D scene
//   Drop:FILE;FILE…         files dropped on the window together (the lesson among them opens)
#pragma once

#include <SDL.h>

#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

namespace hsr::viz {

struct ScriptedInput {
    enum class Kind { key, drag, shift_drag, right_click, drop };
    Kind kind = Kind::key;
    std::string key;            // Kind::key: the key's name
    glm::dvec2 from{0}, to{0};  // mouse gestures: world points in the plane z = 0
    std::vector<std::string> files;  // Kind::drop
};

// nullopt for a token that is neither a known key nor a well-formed gesture.
std::optional<ScriptedInput> parse_scripted_input(const std::string& token);

// "Space", "Right", "Shift+Left", … as an SDL key press; false for a name SDL does not know.
bool key_event(const std::string& name, SDL_Event& e);
// A mouse button press or release at a window point.
SDL_Event mouse_button_event(bool down, Uint8 button, int x, int y);
SDL_Event mouse_motion_event(int x, int y, int dx, int dy, bool left_held);
// A file dropped on the window, pushed as SDL tells of one (SDL_DROPFILE; the window frees the name).
void push_file_drop(const std::string& path);

struct LessonPlay;
struct Renderer;
// The next --keys token pushed through SDL's queue as a person's key or gesture would be (a gesture's points through
// the view the last frame drew; `shift_held` when it holds Shift down, to let go after the frame). False: unknown.
bool push_scripted_input(const std::string& token, LessonPlay& lp, const Renderer& r, bool& shift_held);

}  // namespace hsr::viz
