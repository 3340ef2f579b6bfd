// SPDX-License-Identifier: MIT
// The reference Roberts' hidden lines are checked against: points sampled along every drawn edge, each tested by a
// ray cast in world space from the point toward the eye (orthographic: along the view direction) and clipped by
// every other body's planes (Cyrus–Beck), with no perspective transform. Points whose ray only grazes a body, or
// that lie within 1e-6 of a hidden part's end, are left out as undecidable.
#pragma once

#include <cstdint>

#include "roberts/hidden_lines.h"

namespace hsr::analysis {

struct LineAgreement {
    std::uint64_t compared = 0, unsure = 0, wrong = 0;
};

LineAgreement against_rays(const algo::Scene& scene, const algo::LineDrawing& drawing, int samples_per_edge);

}  // namespace hsr::analysis
