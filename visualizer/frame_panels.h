// SPDX-License-Identifier: MIT
// Everything of a frame but GL's part: the panel column arranged, the family's 3D view as lines and labels (for the
// window's GL to draw), and every panel Dear ImGui draws: the load error, or the family's canvases and state panel,
// then what every lesson has (lesson, pseudocode, question, overlays, notes, narration, timeline). The window calls
// it each frame; the panel fuzzer (tests/fuzz/fuzz_panels.cpp) calls it with no window, so it draws what the class sees.
#pragma once

#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "lesson_play.h"
#include "panels/lesson_panels.h"
#include "panels/ui_actions.h"
#include "render/line_batch.h"
#include "screens/screen.h"

namespace hsr::viz {

// The frame's layout in a window of width × height points: the column as wide as the lesson's side and scale say
// (within the window), the timeline under the view, the column's boxes arranged to their content.
PanelLayout arrange_frame(LessonPlay& lp, float width, float height);

// The 3D view of the lesson playing into `lines` and `labels` (cleared first; the labels drawn), then every panel.
// Returns the view-projection the lines are to be drawn with (the family's own camera, else the orbit camera).
glm::mat4 draw_frame_content(LessonPlay& lp, LineBatches& lines, std::vector<Label>& labels, const PanelLayout& layout,
                             UiActions& actions);

// `detail`: the caption the family's draw_scene gave; view_w × view_h: the 3D view the canvases cover.
void draw_frame_panels(LessonPlay& lp, const std::string& detail, float view_w, float view_h, const PanelLayout& layout,
                       UiActions& actions);

}  // namespace hsr::viz
