// SPDX-License-Identifier: MIT
// The panels of a depth-sort lesson: the decision table of the pair under examination (each test tried, its
// outcome and the numbers that decided it), and over the 3D view the display list (moves and splits animated),
// the screen with the projections of R and Q (tests 1, 2 and 5 are about them) and the image painted so far.
#pragma once

#include <vector>

#include <imgui.h>

#include "panels/lesson_panels.h"
#include "raster/image.h"
#include "state/label_placement.h"
#include "state/depth_sort_session.h"

namespace hsr::viz {

void depth_sort_state_panel(const DepthSortSession& s, const PanelLayout& layout);
// Where each chip of the display list is drawn now, by polygon index (NaN: not placed yet); its screen keeps it
// between frames.
struct ChipPlaces {
    std::vector<float> x;
};
// Over the view area (x, y, w, h): the display list along the top, the screen bottom left, `painted` (the image
// painted so far) bottom right. With `animate` off (screenshots, recordings) the chips stand in their places at once.
void depth_sort_canvas(const DepthSortSession& s, ChipPlaces& chips, const algo::Image& painted, float x, float y, float w,
                       float h, bool animate);
// The two insets' squares over the view area (x, y, w, h), each with its title line above it: the 3D view's labels
// keep off them.
struct DepthSortInsets {
    float size;
    ImVec2 screen, painted;  // top left of each square
    std::vector<ViewRect> covered() const;
};
DepthSortInsets depth_sort_insets(float x, float y, float w, float h);

}  // namespace hsr::viz
