// SPDX-License-Identifier: MIT
#include "clipping/liang_barsky.h"

#include <array>

namespace hsr::algo {
namespace {

// The lecture's order i = 1..6 (left, right, bottom, top, near, far), then w ≥ ε in homogeneous clip space.
constexpr std::array<ClipPlane, 7> lecture_order = {ClipPlane::x_min, ClipPlane::x_max, ClipPlane::y_min,
                                                    ClipPlane::y_max, ClipPlane::z_min, ClipPlane::z_max,
                                                    ClipPlane::w_min};

Steps<ClipEvent, SegmentClip> liang_barsky_machine(ClipSegment segment, ClipOptions o) {
    const Vec4 p1 = segment.p1, p2 = segment.p2;
    const ClipSpace s = o.space;
    co_yield SegmentStarted{segment.id, p1, p2};

    double t_enter = 0, t_leave = 1;
    ClipPlane enter_plane = ClipPlane::w_min, leave_plane = ClipPlane::w_min;
    for (int k = 0; k < plane_count(s); ++k) {
        const ClipPlane r = lecture_order[k];
        // t·p ≤ q, e.g. p_1 = −Δx − Δw, q_1 = x1 + w1: the boundary value falls by p per unit t
        const double q = boundary_value(p1, r, s);
        const double p = q - boundary_value(p2, r, s);
        if (p == 0) {  // parallel to the plane: wholly inside or wholly outside it, no division
            const bool inside = q >= 0;
            co_yield BoundaryTested{r, inside ? BoundaryCase::parallel_inside : BoundaryCase::parallel_outside, p, q};
            if (!inside) {
                co_yield SegmentEmptied{r, t_enter, t_leave};
                co_yield SegmentFinished{segment.id, ClipOutcome::rejected, {}, {}};
                co_return SegmentClip{};
            }
            continue;
        }
        const double ratio = q / p;
        if (p < 0) {  // entering: t ≥ q/p
            co_yield BoundaryTested{r, BoundaryCase::entering, p, q};
            if (ratio > t_enter) {
                co_yield ParameterUpdated{Parameter::t_enter, t_enter, ratio};
                t_enter = ratio;
                enter_plane = r;
            }
        } else {  // leaving: t ≤ q/p
            co_yield BoundaryTested{r, BoundaryCase::leaving, p, q};
            if (ratio < t_leave) {
                co_yield ParameterUpdated{Parameter::t_leave, t_leave, ratio};
                t_leave = ratio;
                leave_plane = r;
            }
        }
        if (t_enter > t_leave) {  // the early exit
            co_yield SegmentEmptied{r, t_enter, t_leave};
            co_yield SegmentFinished{segment.id, ClipOutcome::rejected, {}, {}};
            co_return SegmentClip{};
        }
    }

    // The visible part is l(t_enter) … l(t_leave), each end snapped onto the plane that set it.
    const bool cut = t_enter > 0 || t_leave < 1;
    const Vec4 a = t_enter > 0 ? intersect_plane_line(enter_plane, s, p1, p2, t_enter) : p1;
    const Vec4 b = t_leave < 1 ? intersect_plane_line(leave_plane, s, p1, p2, t_leave) : p2;
    const SegmentClip answer{cut ? ClipOutcome::clipped : ClipOutcome::inside, a, b};
    co_yield SegmentFinished{segment.id, answer.outcome, a, b};
    co_return answer;
}

}  // namespace

Steps<ClipEvent, SegmentClip> liang_barsky(ClipSegment segment, ClipOptions options) {
    require_clippable(segment);
    return liang_barsky_machine(segment, options);
}

}  // namespace hsr::algo
