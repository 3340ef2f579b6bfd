// SPDX-License-Identifier: MIT
// Inputs, options and answers of the clipping machines (clip-space coordinates throughout).
#pragma once

#include <cstdint>
#include <vector>

#include "clipping/clip_events.h"

namespace hsr::algo {

struct ClipPoint {
    PrimitiveId id = 0;
    Vec4 p{0, 0, 0, 1};
};
struct ClipSegment {
    PrimitiveId id = 0;
    Vec4 p1{0, 0, 0, 1}, p2{0, 0, 0, 1};
};
struct ClipPolygon {
    PrimitiveId id = 0;
    std::vector<Vec4> vertices;  // in order; the last connects back to the first
};

struct ClipOptions {
    ClipSpace space = ClipSpace::homogeneous;
    std::uint32_t max_rounds = 0;          // Cohen–Sutherland intersections per segment; 0 means one per plane
    std::uint32_t max_vertices = 1u << 22;  // Sutherland–Hodgman: largest polygon a stage may take or pass on
};

// The visible part of a segment: [a, b] unless rejected. `bounded` is set when a step bound stopped the machine.
struct SegmentClip {
    ClipOutcome outcome = ClipOutcome::rejected;
    Vec4 a{}, b{};
    bool bounded = false;
    bool operator==(const SegmentClip&) const = default;
};

struct PolygonClip {
    ClipOutcome outcome = ClipOutcome::rejected;
    std::vector<Vec4> vertices;
    bool bounded = false;
    bool operator==(const PolygonClip&) const = default;
};

// Throw InvalidInput naming the primitive and coordinate when any coordinate is NaN, infinite or beyond
// ±ClipTolerance::largest_coordinate.
void require_clippable(const ClipSegment& s);
void require_clippable(const ClipPolygon& p);
void require_clippable(const ClipPoint& p);

}  // namespace hsr::algo
