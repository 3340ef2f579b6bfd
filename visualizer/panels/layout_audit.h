// SPDX-License-Identifier: MIT
// What the frame drew cut: a box of the panel column whose content runs past its right or bottom edge with no
// scrollbar to reach it, or a word too wide for its line (broken inside). After --screenshot the window prints each
// as "hsrviz: layout: …"; a GUI test walks every lesson at both sizes and wants none.
#pragma once

#include <string>
#include <vector>

namespace hsr::viz {

// The problems of the frame being drawn (cleared when a frame starts).
std::vector<std::string>& layout_problems();
// Checks the current ImGui window (called before its End).
void audit_current_window();
// A word of the current window broken inside because no line could hold it.
void note_broken_word();
// Whether the frame's state box (what the lesson builds: the tree, the matrix, the tables) scrolls: at the end of a
// lesson that is a problem too (its result must be in full view), which the window says after --screenshot.
bool& result_scrolls();
// The boxes of this frame that scroll (their content taller than they are): not an error, but a class sees only a
// part of them; the window lists them after --screenshot ("hsrviz: scrolls: …"), for the layout's figures.
std::vector<std::string>& scrolling_boxes();

}  // namespace hsr::viz
