// SPDX-License-Identifier: MIT
// One frame of the window drawn: the 3D view's GL lines (the family's screen fills them) under ImGui's panels; and
// the 3D view as the last frame drew it, for picking and for scripted gestures.
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "lesson_play.h"
#include "panels/lesson_panels.h"
#include "panels/ui_actions.h"
#include "render/label.h"
#include "render/line_batch.h"
#include "screens/screen.h"

namespace hsr::viz {

struct Renderer {
    LineBatches batches;
    std::vector<Label> labels;
    ViewGeometry geometry;  // of the last frame's 3D view, for picking
};

// The 3D view as the last frame drew it, with the overlays and the second view as they are now.
ViewGeometry geometry_now(const LessonPlay& lp, const Renderer& r);
// `layout` is in ImGui's units (window points); `scale` turns them into framebuffer pixels (2 on a HiDPI display).
void draw_frame(LessonPlay& lp, Renderer& r, const PanelLayout& layout, float scale, UiActions& actions);
// Where a gesture's point is in the window: a gesture names points as its family's view does (the fat pixels take
// grid pixels, the others the plane z = 0).
glm::vec2 gesture_window_point(LessonPlay& lp, const Renderer& r, glm::dvec2 p);

}  // namespace hsr::viz
