// SPDX-License-Identifier: MIT
// The exact answer of clipping, in GMP rationals: every double input is a rational, and the clip planes are
// linear, so the visible part of a segment or polygon can be computed with no rounding at all. Tests measure the
// algorithms' error against it, never against the algorithms themselves.
#pragma once

#include <optional>
#include <vector>

#include <gmpxx.h>

#include "clipping/clip_space.h"

namespace hsr::analysis {

using algo::ClipSpace;
using algo::Vec4;

struct ExactPoint {
    mpq_class c[4];
    Vec4 to_double() const { return {c[0].get_d(), c[1].get_d(), c[2].get_d(), c[3].get_d()}; }
};

struct ExactSegment {
    bool visible = false;
    ExactPoint a, b;
    bool cut = false;  // some part was clipped away
};

ExactSegment exact_clip_segment(const Vec4& p1, const Vec4& p2, ClipSpace s);
// Sutherland–Hodgman in rationals: exact intersections, exact inside tests.
std::vector<ExactPoint> exact_clip_polygon(const std::vector<Vec4>& polygon, ClipSpace s);

// |a − b|∞ / max(1, scale)
double relative_error(const Vec4& a, const ExactPoint& b, double scale);
// A clipped polygon's error: the largest relative_error of a vertex of either set from the nearest of the other
// (each vertex near some exact one, and each exact one near some vertex).
double vertex_set_error(const std::vector<Vec4>& got, const std::vector<ExactPoint>& exact, double scale);

}  // namespace hsr::analysis
