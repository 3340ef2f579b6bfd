// SPDX-License-Identifier: MIT
// Newell, Newell and Sancha's depth sort, as the lectures give it:
//
//   DepthSort(polygonDB):
//     for each polygon find MINZ and MAXZ; sort by depth, farthest first
//     resolve overlaps in z:
//       R = the head of the list; for each Q whose z extent overlaps R's, R may be drawn before Q if
//         1. the x extents do not overlap, or 2. the y extents do not overlap, or
//         3. R is wholly behind Q's plane (away from the viewpoint), or 4. Q is wholly in front of R's plane, or
//         5. the projections of R and Q do not overlap
//       if none holds, swap the roles and retry 3 and 4: if one holds, Q moves to the head of the list;
//       if not, or if Q has moved before (a cycle), split R by the plane of Q (or Q by R's, if Q's does not cut R)
//       and carry on
//     display the polygons in the order of the list (back to front)
//
// It works in the canonical view volume, after clipping in homogeneous clip space and the divide by w, for
// perspective and orthographic cameras alike: the viewpoint is then at z = −∞ and every ray runs along z.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/plane.h"
#include "core/steps.h"
#include "depth_sort/depth_sort_events.h"
#include "raster/screen_polygon.h"

namespace hsr::algo {

struct SortPolygon {
    SceneId id = 0;
    Color color;
    std::vector<Vec3> vertices;  // normalised device coordinates, convex, after clipping to the view volume
    double opacity = 1;
};

struct DepthSortOptions {
    std::uint32_t max_splits = 4096;                    // step bound: splits in all
    // step bound: pairs examined in all; by default 256 n² for n polygons, at least 10^5 and at most 5·10^7 (a few
    // seconds): a sort of n polygons examines far fewer, so reaching it means the input defeats the algorithm
    std::optional<std::uint64_t> max_pairs;
    // the notes' optimisation of the display step: after the sort, draw the list front to back on a screen of this
    // size, each pixel once, and stop when every pixel is written (front_to_back.h); its events follow the sort's
    std::optional<Viewport> front_to_back;
};

struct DepthSortResult {
    std::vector<SortPolygon> polygons;  // the working list: the inputs, then the parts of splits
    std::vector<std::uint32_t> order;   // indices into polygons, back to front: the painter's order
    std::uint32_t splits = 0, moves = 0;
    std::uint64_t pairs = 0;
    std::uint64_t decided_by[7] = {};   // how often each OrderTest settled a pair
    bool bounded = false;
};

Steps<DepthSortEvent, DepthSortResult> depth_sort(std::vector<SortPolygon> polygons, DepthSortOptions options = {});

// The scene's polygons clipped to its camera's view volume and put in normalised device coordinates (polygons
// wholly outside are left out). InvalidInput names a polygon with NaN coordinates or that is not convex.
std::vector<SortPolygon> sort_polygons(const Scene& scene);

}  // namespace hsr::algo
