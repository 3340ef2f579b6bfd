// SPDX-License-Identifier: MIT
// The trace's fields of z-merge's events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "zbuffer/z_merge.h"

namespace hsr::algo {

HSR_TO_JSON(PixelMerged, x, y, depth_a, depth_b, from_a)
HSR_TO_JSON(MergeFinished, from_a, from_b, background)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::ZMergeEvent)
}  // namespace hsr::viz
