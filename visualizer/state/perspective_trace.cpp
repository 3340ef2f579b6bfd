// SPDX-License-Identifier: MIT
// The trace's fields of the perspective transform's events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "perspective/transform_events.h"

namespace hsr::algo {

HSR_TO_JSON(VolumeShown, perspective, near, far, points)
HSR_TO_JSON(WarpStep, stage, s, perspective)
HSR_TO_JSON(PointTransformed, point, x, y, z, w, nx, ny, nz)
HSR_TO_JSON(PointLeftOut, point, behind_eye)
HSR_TO_JSON(PairCompared, a, b, ratio_ax, ratio_ay, ratio_bx, ratio_by, same_before, same_after, nearer)
HSR_TO_JSON(TransformFinished, points, left_out, pairs, comparisons, divisions_before, divisions_after, disagreements, bounded)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::TransformEvent)
}  // namespace hsr::viz
