// SPDX-License-Identifier: MIT
// A box in the view's right part for what a lesson builds (the BSP tree, the faces' table), where a class sees it
// whole at every step, instead of behind the column's scrollbar; the screen frames its scene left of it
// (frame_left_of_side_box in screens/screen.h).
#pragma once

#include <string>

#include <imgui.h>

#include "panels/panel_style.h"

namespace hsr::viz {

inline constexpr float side_box_share = 0.36f;  // of the view's width, unless a box asks for another share

// Whether such a box is wide enough for its content at this type size (14 lines' height across); a view too narrow
// (large type on a small window) keeps the content in the column's state box instead.
inline bool side_box_fits(float view_w, float share = side_box_share) { return view_w * share >= 14 * ImGui::GetFontSize(); }

// Begins the box (end it with end_view_side_box), `below` points above the view's foot kept free.
inline void begin_view_side_box(const std::string& title, float view_w, float view_h, float below = 0, float share = side_box_share) {
    const float x = view_w * (1 - share), w = view_w * share - 8, h = view_h - below - 16;
    place(x, 8, w, h);
    ImGui::Begin(title.c_str(), nullptr, fixed | ImGuiWindowFlags_NoBringToFrontOnFocus);
}

// A box across the view's foot for a wide table (the points of the perspective transform), `share` of the view's
// height; the screen frames its scene above it (frame_above_foot_box in screens/screen.h). End it with end_view_side_box.
inline bool foot_box_fits(float view_w) { return view_w >= 28 * ImGui::GetFontSize(); }
inline void begin_view_foot_box(const std::string& title, float view_w, float view_h, float share) {
    const float h = view_h * share;
    place(8, view_h - h, view_w - 16, h - 8);
    ImGui::Begin(title.c_str(), nullptr, fixed | ImGuiWindowFlags_NoBringToFrontOnFocus);
}

inline void end_view_side_box() {
    audit_current_window();
    ImGui::End();
}

}  // namespace hsr::viz
