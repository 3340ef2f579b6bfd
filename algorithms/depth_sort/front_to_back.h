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

struct FrontPolygonDrawn {
    static constexpr std::string_view kind = "FrontPolygonDrawn";
    std::uint32_t polygon;   // in the sort's working list
    SceneId id;
    std::uint32_t written;   // pixels it wrote (none nearer had)
    std::uint32_t hidden;    // pixels it covers that nearer polygons had written: not drawn again
    std::uint32_t unwritten; // pixels of the screen still unwritten after it
    bool operator==(const FrontPolygonDrawn&) const = default;
};
struct ScreenFilled {
    static constexpr std::string_view kind = "ScreenFilled";
    std::uint32_t drawn, left;  // polygons drawn when every pixel was written; polygons left undrawn
    bool operator==(const ScreenFilled&) const = default;
};
struct FrontDisplayFinished {
    static constexpr std::string_view kind = "FrontDisplayFinished";
    std::uint32_t drawn, unwritten;  // the whole list drawn; pixels left to the background
    bool operator==(const FrontDisplayFinished&) const = default;
};
using FrontToBackEvent = std::variant<FrontPolygonDrawn, ScreenFilled, FrontDisplayFinished>;
std::string describe(const FrontToBackEvent& e);

struct FrontToBackResult {
    Image image{0, 0};
    std::uint32_t drawn = 0, left = 0;  // polygons drawn, and left undrawn when the screen filled
};

// `order` is the sort's painter's order, back to front (DepthSortResult::order); it is walked from its end.
Steps<FrontToBackEvent, FrontToBackResult> display_front_to_back(std::vector<SortPolygon> polygons, std::vector<std::uint32_t> order,
                                                                 Viewport viewport, Color background = {26, 28, 33});

}  // namespace hsr::algo
