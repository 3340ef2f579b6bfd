// SPDX-License-Identifier: MIT
#include "clipping/cohen_sutherland.h"

#include "clipping/carried_boundaries.h"

namespace hsr::algo {
namespace {

ClipPlane plane_where_bits_differ(Outcode c1, Outcode c2) {
    for (ClipPlane r : all_planes)
        if (c1.has(r) != c2.has(r)) return r;
    return ClipPlane::z_max;  // unreachable: called only when c1 != c2
}

struct Round {
    std::uint8_t number;  // 1 for the first call
    Outcode allowed;      // planes the segment may still cross
    std::uint32_t limit;  // the step bound on intersections
};

// The segment the user gave, and where on it the current p1 and p2 lie (t1 < t2 along p1 → p2 of the input).
struct Original {
    Vec4 p1, p2;
    double t1 = 0, t2 = 1;
};

// mkcode of the current endpoint at parameter t of the original segment, from the original's boundary values
// (boundary_at in carried_boundaries.h): the same bits as mkcode(p) of the exact point, where the rounded point may sit on
// a plane the exact one is just outside of (and the segment would be kept far along a near-parallel face).
Outcode outcode_on(const Original& o, double t, ClipSpace s) {
    Outcode c;
    for (int k = 0; k < plane_count(s); ++k) {
        const ClipPlane r = all_planes[k];
        if (boundary_at(boundary_value(o.p1, r, s), boundary_value(o.p2, r, s), t) < 0) c.bits |= Outcode::mask(r);
    }
    return c;
}

// CS_Clip_3D(p1, p2) of the lecture. A plane both endpoints are inside of cannot be crossed by the segment between
// them, and the plane just clipped against is never crossed again; `allowed` keeps only the rest, so every round
// removes one plane and rounding in an intersection cannot set a bit that makes the recursion spin.
Steps<ClipEvent, SegmentClip> cs_clip_3d(Vec4 p1, Vec4 p2, ClipSpace s, Round round, Original original) {
    const Outcode c1 = outcode_on(original, original.t1, s) & round.allowed;
    co_yield OutcodeComputed{Endpoint::p1, c1, round.number, p1};
    const Outcode c2 = outcode_on(original, original.t2, s) & round.allowed;
    co_yield OutcodeComputed{Endpoint::p2, c2, round.number, p2};
    co_yield CodesCompared{c1, c2};

    if ((c1 | c2).inside()) {  // p1p2 is inside
        co_yield TriviallyAccepted{c1, c2};
        co_return SegmentClip{round.number > 1 ? ClipOutcome::clipped : ClipOutcome::inside, p1, p2};
    }
    if (!(c1 & c2).inside()) {  // p1p2 is outside
        co_yield TriviallyRejected{c1, c2};
        co_return SegmentClip{ClipOutcome::rejected, {}, {}};
    }
    if (round.number > round.limit) {
        co_yield StepBoundReached{Bound::rounds, round.limit};
        co_return SegmentClip{ClipOutcome::clipped, p1, p2, true};
    }

    // R = frustum plane with (c1 bit != c2 bit)
    const ClipPlane r = plane_where_bits_differ(c1, c2);
    const bool p1_outside = c1.has(r);  // outside(R, p1)
    co_yield PlaneChosen{r, p1_outside ? Endpoint::p1 : Endpoint::p2};

    // i = intersect_plane_line(R, (p1, p2)), by equations (3), on the original segment (see carried_boundaries.h)
    const double t_original = cut_parameter(boundary_value(original.p1, r, s), boundary_value(original.p2, r, s),
                                            original.t1, original.t2, p1_outside);
    const Vec4 i = intersect_plane_line(r, s, original.p1, original.p2, t_original);
    const double span = original.t2 - original.t1;
    const double t = span > 0 ? (t_original - original.t1) / span : 0.0;  // along the current p1 → p2, as shown
    co_yield IntersectionComputed{r, p1_outside ? Endpoint::p1 : Endpoint::p2, t, i};

    const Round next{std::uint8_t(round.number + 1), Outcode{std::uint8_t((c1 | c2).bits & ~Outcode::mask(r))},
                     round.limit};
    (p1_outside ? original.t1 : original.t2) = t_original;
    auto rest = p1_outside ? cs_clip_3d(i, p2, s, next, original) : cs_clip_3d(p1, i, s, next, original);
    for (const auto& e : rest) co_yield e;
    co_return rest.result();
}

Steps<ClipEvent, SegmentClip> cohen_sutherland_machine(ClipSegment segment, ClipOptions o) {
    co_yield SegmentStarted{segment.id, segment.p1, segment.p2};
    const std::uint32_t limit = o.max_rounds != 0 ? o.max_rounds : std::uint32_t(plane_count(o.space));
    auto clip = cs_clip_3d(segment.p1, segment.p2, o.space, Round{1, Outcode{0x7f}, limit}, {segment.p1, segment.p2});
    for (const auto& e : clip) co_yield e;
    const SegmentClip& answer = clip.result();
    co_yield SegmentFinished{segment.id, answer.outcome, answer.a, answer.b};
    co_return answer;
}

}  // namespace

Steps<ClipEvent, SegmentClip> cohen_sutherland(ClipSegment segment, ClipOptions options) {
    require_clippable(segment);
    return cohen_sutherland_machine(segment, options);
}

}  // namespace hsr::algo
