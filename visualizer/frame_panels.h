// Everything of a frame that Dear ImGui draws, and nothing that GL does: the load error, or the family's canvases and
// state panel, then what every lesson has (lesson, pseudocode, question, overlays, notes, narration, timeline). The
// window calls it after drawing the 3D view; the panel fuzzer (tests/fuzz/fuzz_panels.cpp) calls it with no window.
#pragma once

#include <string>

#include "lesson_play.h"
#include "panels/lesson_panels.h"
#include "panels/ui_actions.h"

namespace hsr::viz {

// `detail`: the caption the family's draw_scene gave; view_w × view_h: the 3D view the canvases cover.
void draw_frame_panels(Lessonplay& lp, const std::string& detail, float view_w, float view_h, const PanelLayout& layout,
                       UiActions& actions);

}  // namespace hsr::viz
