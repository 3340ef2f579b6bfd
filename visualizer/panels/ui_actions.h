// SPDX-License-Identifier: MIT
// What the user asked for this frame. Panels and keys fill it in; the app carries it out in its update step,
// so panels never change state themselves.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "bsp/bsp_events.h"
#include "zbuffer/depth_format.h"

namespace hsr::viz {

struct UiActions {
    bool toggle_play = false;
    bool step = false, step_back = false;              // to the next / previous major event
    bool micro_step = false, micro_step_back = false;  // one event
    bool to_start = false, to_end = false;
    std::optional<std::size_t> seek;
    std::optional<float> speed;  // steps per second while playing
    bool reload = false;
    std::optional<glm::dvec3> move_eye;  // the eye dragged to here (world space)
    std::optional<algo::DepthFormat> depth_format;  // z-buffer lessons: rerun with this format
    std::optional<algo::DepthRange> depth_range;    // z-buffer lessons: rerun with this near and far
    bool toggle_3d = false;                         // z-buffer lessons: the fat pixels, or the scene in 3D
    std::optional<algo::Order> bsp_order;           // BSP lessons: DisplayBSP back to front or front to back
    std::optional<algo::SplitterRule> bsp_splitter; // BSP lessons: rebuild with this rule
    bool bsp_reverse = false, bsp_shuffle = false;  // BSP lessons: the insertion order reversed, or shuffled
    std::optional<bool> find_piercings;             // classic scan line: rerun with or without the extra intersections
    std::optional<int> digit;                       // a number key: a question's choice when one is open, else its own use
    std::optional<std::string> answer;              // a question's choice, clicked
    bool next_chapter = false, previous_chapter = false, next_language = false;
    bool toggle_keys = false, close_overlays = false;  // F1, Esc
    bool export_all = false;                           // E: the window as PNG, the trace, the scene as TOML
    struct VertexMove {
        std::size_t input, vertex;
        glm::dvec3 to;  // world space
    };
    std::optional<VertexMove> move_vertex;             // a 2D scene's vertex dragged here
    bool undo = false, redo = false, save_scene = false;  // Ctrl+Z, Ctrl+Y, S
    std::optional<std::pair<glm::dvec3, glm::dvec3>> add_segment;  // Shift+drag in a 2D scene: a new segment
    std::optional<std::size_t> delete_input;                       // right-click on a 2D scene's segment
    // z-buffer lessons, in the fat-pixel view: a scene vertex dragged to a pixel position, a triangle drawn, a polygon
    // right-clicked away (positions in pixels of the grid, x right and y down)
    struct ScreenVertexMove {
        std::size_t polygon, vertex;
        glm::dvec2 pixel;
    };
    std::optional<ScreenVertexMove> move_screen_vertex;
    std::optional<std::array<glm::dvec2, 3>> add_triangle;
    std::optional<std::size_t> delete_polygon;
    bool toggle_presets = false;                                   // P
    bool column_narrower = false, column_wider = false;            // [ and ]
    int scale_step = 0;                                            // Ctrl+= +1, Ctrl+− −1; Ctrl+0: back to the start
    bool scale_reset = false;
    bool toggle_report = false;                                    // R
    bool cancel_measurement = false;                               // the report's Cancel button
    std::optional<int> preset;                                     // an extreme case chosen (its index)
    bool random_scene = false, back_to_lesson = false;             // 0 and B while the presets show
    int next_lesson = 0;                                           // N: +1, Shift+N: −1 (the course's order)
    bool toggle_menu = false;                                      // M: the lesson menu
    std::optional<std::string> open_lesson;                        // a lesson chosen in the menu, or a file dropped (its path)
    bool open_file = false;                                        // O: a lesson or scene file of the person's own
    int up_down = 0;                                               // ↑ −1, ↓ +1 (the menu's highlight)
    int forward = 0, left = 0;  // ↑ +1 ↓ −1, ← +1 → −1: a screen's drive mode (2D BSP) takes them instead of the steps
    // W: walk through a culling scene (the arrows walk and turn, a drag looks around); a stage switched on or off
    // (its index in algo::all_stages), the Hi-Z stage's frame-to-frame coherence
    bool toggle_walk = false;
    std::optional<int> walk_stage;
    std::optional<bool> walk_coherent;
    bool enter = false;                                            // Enter (opens the highlighted lesson)
    // X: practice; a key for the number being typed ('.', ',', '-', '\b' for Backspace; digits come as `digit`)
    bool toggle_practice = false;
    std::optional<char> typed;
    struct PracticeChoice {
        std::size_t topic;
        int level;
        std::uint64_t series;
    };
    std::optional<PracticeChoice> practice_choice;                 // another topic, level or series in the practice box
    bool practice_next = false;                                    // the practice box's Next exercise button
};

struct PlaybackState {
    bool playing = false;
    float speed = 2.0f;        // steps per second
    double since_step = 0.0;   // seconds since the last automatic step
};

}  // namespace hsr::viz
