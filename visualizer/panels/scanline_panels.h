// SPDX-License-Identifier: MIT
// The panels of a scan-line lesson: the image filled line by line with the current line, its active edges and
// their crossings (classic: where the planes were compared, and the extra intersections); the edge table with the
// active edges marked, and the in/out flags.
#pragma once

#include "panels/lesson_panels.h"
#include "state/scanline_session.h"

namespace hsr::viz {

void scanline_canvas(const ScanLineSession& s, float x, float y, float w, float h);
// The hybrid's edge table with the in/out flags; the classic's edge table in the notes' fields (x, y_max, Δx) and its
// polygon table (plane equation, in/out), with the switch for the extra intersections where polygons pierce.
void scanline_state_panel(const ScanLineSession& s, const PanelLayout& layout, UiActions& out);
// The same tables in the view's right part (panels/view_side_box.h), the image left of them, where they show whole at
// every step (in the column they had a row and a half at 1280×800).
inline constexpr float scanline_tables_share = 0.48f;
void scanline_tables_box(const ScanLineSession& s, float view_w, float view_h, UiActions& out);
// The hybrid's edge table has a row per edge: under the image, across the view, it lets the image grow (at
// 1280×800 its pixels half as large again as beside the table). The share of the view's height that box takes, or
// 0 where the table is better beside the image (the classic's two tables, a view too short or too narrow).
float scanline_foot_share(const ScanLineSession& s, float view_w, float view_h);
void scanline_tables_foot_box(const ScanLineSession& s, float view_w, float view_h, float share, UiActions& out);

}  // namespace hsr::viz
