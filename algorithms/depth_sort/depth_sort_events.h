// SPDX-License-Identifier: MIT
// What Newell's depth sort tells as it runs. Polygons are numbered in the sort's working list of polygons (the
// scene's, clipped to the view volume, then the parts of splits as they are made); each carries its scene id.
// Depths and extents are in the canonical view volume (normalised device coordinates: x, y, z in [−1, 1], z
// growing away from the eye), where the lecture says hidden-surface elimination happens.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <span>
#include <variant>
#include <vector>

#include "core/phrase.h"
#include "core/plane.h"
#include "scene/scene.h"

namespace hsr::algo {

// The lecture's tests, in order of cost; the swapped retries of 3 and 4 are their own kinds.
enum class OrderTest : std::uint8_t {
    x_extents,          // 1. the x extents of R and Q do not overlap
    y_extents,          // 2. the y extents do not overlap
    r_behind_q,         // 3. R lies wholly in the half-space of Q away from the viewpoint
    q_in_front_of_r,    // 4. Q lies wholly in the half-space of R holding the viewpoint
    projections,        // 5. the projections of R and Q do not overlap
    q_behind_r,         // 3 with the roles swapped
    r_in_front_of_q,    // 4 with the roles swapped
};

struct ListSorted {
    static constexpr std::string_view kind = "ListSorted";
    std::vector<std::uint32_t> order;  // farthest MAXZ first
    bool operator==(const ListSorted&) const = default;
};
struct PairExamined {
    static constexpr std::string_view kind = "PairExamined";
    std::uint32_t r, q;      // R at the head of the list, Q a polygon whose z extent overlaps R's
    double r_min_z, r_max_z, q_min_z, q_max_z;
    bool operator==(const PairExamined&) const = default;
};
struct TestTried {
    static constexpr std::string_view kind = "TestTried";
    OrderTest test;
    bool passed;
    double a, b, c, d;  // extents: R's [a, b] and Q's [c, d]; plane tests: vertices on the far side (a), on the
                        // viewer's side (b), on the plane (c), the viewer's side (d: +1 front, −1 back, 0 in plane);
                        // projections: a = 1 when they overlap
    bool operator==(const TestTried&) const = default;
};
struct PolygonMoved {
    static constexpr std::string_view kind = "PolygonMoved";
    std::uint32_t polygon, ahead_of;  // Q goes to the head of the list, to be drawn before R
    bool operator==(const PolygonMoved&) const = default;
};
struct CycleDetected {
    static constexpr std::string_view kind = "CycleDetected";
    std::uint32_t polygon;  // it would move a second time
    bool operator==(const CycleDetected&) const = default;
};
struct PolygonCut {
    static constexpr std::string_view kind = "PolygonCut";
    std::uint32_t polygon, by;     // cut by the plane of `by`
    std::uint32_t front, back;     // the new parts, which take its place in the list (back part first)
    std::vector<Vec3> front_vertices, back_vertices;
    bool across = false;           // cut across its length by a plane along the view rays instead (`by` is itself):
                                   // no plane of the cycle cut another of its members
    bool operator==(const PolygonCut&) const = default;
};
struct PolygonPainted {
    static constexpr std::string_view kind = "PolygonPainted";
    std::uint32_t polygon;
    SceneId id;
    bool deferred = false;  // the display is front to back: R joins the output list, drawn in the display step
    bool operator==(const PolygonPainted&) const = default;
};
struct DepthSortFinished {
    static constexpr std::string_view kind = "DepthSortFinished";
    std::uint32_t drawn, splits, moves;
    std::uint64_t pairs;
    bool operator==(const DepthSortFinished&) const = default;
};
enum class SortBound : std::uint8_t { splits, pairs };
struct SortBoundReached {
    static constexpr std::string_view kind = "SortBoundReached";
    SortBound bound;
    std::uint64_t limit;
    bool operator==(const SortBoundReached&) const = default;
};

// The display step front to back (front_to_back.h), when the sort is asked for it: after the sort, the list drawn
// nearest first, each pixel written once, until the screen is full.
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
using DepthSortEvent = std::variant<ListSorted, PairExamined, TestTried, PolygonMoved, CycleDetected, PolygonCut,
                                    PolygonPainted, DepthSortFinished, SortBoundReached, FrontPolygonDrawn, ScreenFilled,
                                    FrontDisplayFinished>;

// What an event says, as a template with named values (core/phrase.h), and in English.
Phrase phrase(const DepthSortEvent& e);
std::string describe(const DepthSortEvent& e);
std::string_view to_string(OrderTest t);
const Saying& term(OrderTest t);  // a test's name, to translate
std::span<const Saying> depth_sort_sayings();  // every template the depth sort says

}  // namespace hsr::algo
