// SPDX-License-Identifier: MIT
// The facts the clipping machines report: point clipping, 3D Cohen–Sutherland, 3D Liang–Barsky and the
// Sutherland–Hodgman pipeline share one variant, because they share one picture (the clip volume and the
// primitive being cut down). Every event carries the numbers its sentence and its view need; coordinates are
// clip-space (x, y, z, w). Events are small on purpose: the player stores millions of them.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <span>
#include <variant>

#include "clipping/clip_space.h"
#include "core/events.h"
#include "core/phrase.h"

namespace hsr::algo {

using PrimitiveId = std::int32_t;  // as the scene numbers its primitives

enum class Endpoint : std::uint8_t { p1 = 1, p2 = 2 };
enum class ClipOutcome : std::uint8_t { inside, clipped, rejected };
enum class Bound : std::uint8_t { rounds, vertices };  // which step bound stopped a machine

// ── Point clipping ──────────────────────────────────────────────────────────────────────────────────────────
struct PointClassified {
    static constexpr std::string_view kind = "PointClassified";
    PrimitiveId id;
    Outcode code;
    Vec4 p;
    bool operator==(const PointClassified&) const = default;
};

// ── Segments (Cohen–Sutherland and Liang–Barsky) ────────────────────────────────────────────────────────────
struct SegmentStarted {
    static constexpr std::string_view kind = "SegmentStarted";
    PrimitiveId id;
    Vec4 p1, p2;
    bool operator==(const SegmentStarted&) const = default;
};

// c = mkcode(p): one endpoint of the current (possibly already shortened) segment.
struct OutcodeComputed {
    static constexpr std::string_view kind = "OutcodeComputed";
    Endpoint endpoint;
    Outcode code;
    std::uint8_t round;  // 1 for the first call of CS_Clip_3D, 2 for its first recursion, …
    Vec4 p;
    bool operator==(const OutcodeComputed&) const = default;
};

// The two tests of the pseudocode: c1 | c2 == 0 accepts, c1 & c2 != 0 rejects, otherwise the segment is cut.
struct CodesCompared {
    static constexpr std::string_view kind = "CodesCompared";
    Outcode c1, c2;
    bool operator==(const CodesCompared&) const = default;
};
struct TriviallyAccepted {
    static constexpr std::string_view kind = "TriviallyAccepted";
    Outcode c1, c2;
    bool operator==(const TriviallyAccepted&) const = default;
};
struct TriviallyRejected {
    static constexpr std::string_view kind = "TriviallyRejected";
    Outcode c1, c2;
    bool operator==(const TriviallyRejected&) const = default;
};

// R = a frustum plane where the bits of c1 and c2 differ; `outside` is the endpoint outside R.
struct PlaneChosen {
    static constexpr std::string_view kind = "PlaneChosen";
    ClipPlane plane;
    Endpoint outside;
    bool operator==(const PlaneChosen&) const = default;
};

// i = intersect_plane_line(R, p1, p2); i replaces the endpoint that is outside R.
struct IntersectionComputed {
    static constexpr std::string_view kind = "IntersectionComputed";
    ClipPlane plane;
    Endpoint replaces;
    double t;  // along the current p1 → p2
    Vec4 point;
    bool operator==(const IntersectionComputed&) const = default;
};

// Liang–Barsky: one inequality t·p_i ≤ q_i (i = 1..6, 7 for w ≥ ε).
enum class BoundaryCase : std::uint8_t { parallel_inside, parallel_outside, entering, leaving };
struct BoundaryTested {
    static constexpr std::string_view kind = "BoundaryTested";
    ClipPlane plane;
    BoundaryCase how;
    double p, q;  // the lecture's p_i, q_i; q/p is the plane's parameter when p ≠ 0
    bool operator==(const BoundaryTested&) const = default;
};
enum class Parameter : std::uint8_t { t_enter, t_leave };
struct ParameterUpdated {
    static constexpr std::string_view kind = "ParameterUpdated";
    Parameter which;
    double before, after;
    bool operator==(const ParameterUpdated&) const = default;
};
// The early exit: a parallel boundary outside, or t_enter > t_leave.
struct SegmentEmptied {
    static constexpr std::string_view kind = "SegmentEmptied";
    ClipPlane plane;
    double t_enter, t_leave;
    bool operator==(const SegmentEmptied&) const = default;
};

// The answer for one segment; a and b are the visible part (equal to the input when inside, unset when rejected).
struct SegmentFinished {
    static constexpr std::string_view kind = "SegmentFinished";
    PrimitiveId id;
    ClipOutcome outcome;
    Vec4 a, b;
    bool operator==(const SegmentFinished&) const = default;
};

// ── Polygons (Sutherland–Hodgman, one pipeline stage per plane) ─────────────────────────────────────────────
struct PolygonStarted {
    static constexpr std::string_view kind = "PolygonStarted";
    PrimitiveId id;
    std::uint32_t vertices;
    bool operator==(const PolygonStarted&) const = default;
};
struct StageStarted {
    static constexpr std::string_view kind = "StageStarted";
    ClipPlane plane;
    std::uint32_t input_vertices;
    bool operator==(const StageStarted&) const = default;
};
// The edge from input vertex s = `from` to its successor e, by the inside test of both ends:
//   in→in emits e; in→out emits i; out→out emits nothing; out→in emits i, then e.
enum class EdgeCase : std::uint8_t { in_in, in_out, out_out, out_in };
struct EdgeClassified {
    static constexpr std::string_view kind = "EdgeClassified";
    ClipPlane plane;
    EdgeCase edge_case;
    bool closes;                // the last edge, back to vertex 0
    std::uint32_t from;         // index of s in the stage's input; e is from + 1, or 0 when the edge closes
    double bc_from, bc_to;      // boundary values of s and e (≥ 0 is inside)
    Vec4 intersection;          // i, for in→out and out→in; unused otherwise
    bool operator==(const EdgeClassified&) const = default;
};
struct StageFinished {
    static constexpr std::string_view kind = "StageFinished";
    ClipPlane plane;
    std::uint32_t output_vertices;
    bool operator==(const StageFinished&) const = default;
};
struct PolygonFinished {
    static constexpr std::string_view kind = "PolygonFinished";
    PrimitiveId id;
    ClipOutcome outcome;
    std::uint32_t vertices;
    bool operator==(const PolygonFinished&) const = default;
};

// ── Bounds ──────────────────────────────────────────────────────────────────────────────────────────────────
// A machine stopped because a step bound was reached; its answer is what it had so far, marked as bounded.
struct StepBoundReached {
    static constexpr std::string_view kind = "StepBoundReached";
    Bound bound;
    std::uint32_t limit;
    bool operator==(const StepBoundReached&) const = default;
};

using ClipEvent = std::variant<PointClassified, SegmentStarted, OutcodeComputed, CodesCompared, TriviallyAccepted,
                               TriviallyRejected, PlaneChosen, IntersectionComputed, BoundaryTested, ParameterUpdated,
                               SegmentEmptied, SegmentFinished, PolygonStarted, StageStarted, EdgeClassified,
                               StageFinished, PolygonFinished, StepBoundReached>;

// The player stores millions of these: keep the most frequent ones small (see tests/bench for the figures).
static_assert(sizeof(EdgeClassified) <= 56);
static_assert(sizeof(OutcodeComputed) <= 40);

// One sentence with the live numbers, for the narration panel, traces and test failures.
// What an event says, as a template with named values (core/phrase.h), and in English.
Phrase phrase(const ClipEvent& e, ClipSpace s);
std::string describe(const ClipEvent& e, ClipSpace s);
const Saying& term(ClipOutcome o);  // words to translate
const Saying& term(BoundaryCase c);
const Saying& term(Bound b);
std::span<const Saying> clipping_sayings();  // every template the clippers say

std::string_view to_string(ClipOutcome o);
std::string_view to_string(EdgeCase c);
std::string_view to_string(BoundaryCase c);
std::string_view to_string(Bound b);
std::string format_point(const Vec4& p, ClipSpace s);  // "(0.5, 1, −0.25)" in the cube, "(0.5, 1, −0.25, 2)" else

}  // namespace hsr::algo
