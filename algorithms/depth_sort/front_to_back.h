// SPDX-License-Identifier: MIT
// The notes' optimisation of depth sort's display step: draw the sorted list from front to back instead,
//
//   DisplayFrontToBack(list):   for each polygon P of the list, nearest first:
//                                 write P on the pixels that no nearer polygon has written
//                                 if every pixel has been written at least once: stop (the rest are hidden)
//
// The image is the back-to-front painter's for opaque polygons, and a screen filled early leaves the farthest
// polygons undrawn. (The written-once rule assumes opaque polygons, as the notes' step does: opacity is ignored.)
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/steps.h"
#include "depth_sort/depth_sort.h"
#include "raster/image.h"
#include "raster/screen_polygon.h"

namespace hsr::algo {

using FrontToBackEvent = std::variant<FrontPolygonDrawn, ScreenFilled, FrontDisplayFinished>;
Phrase phrase(const FrontToBackEvent& e);
std::string describe(const FrontToBackEvent& e);

struct FrontToBackResult {
    Image image{0, 0};
    std::uint32_t drawn = 0, left = 0;  // polygons drawn, and left undrawn when the screen filled
};

// `order` is the sort's painter's order, back to front (DepthSortResult::order); it is walked from its end.
Steps<FrontToBackEvent, FrontToBackResult> display_front_to_back(std::vector<SortPolygon> polygons, std::vector<std::uint32_t> order,
                                                                 Viewport viewport, Color background = {26, 28, 33});

}  // namespace hsr::algo
