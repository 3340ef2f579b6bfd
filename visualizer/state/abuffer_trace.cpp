// SPDX-License-Identifier: MIT
// The trace's fields of the A-buffer's events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "abuffer/abuffer_events.h"

namespace hsr::algo {

HSR_TO_JSON(ABufferStarted, width, height, mask_size, polygons)
HSR_TO_JSON(FragmentMade, polygon, x, y, mask, covered, samples, depth)
HSR_TO_JSON(PolygonScanned, polygon, fragments, opacity)
HSR_TO_JSON(FragmentResolved, x, y, polygon, order, covered, shown, weight)
HSR_TO_JSON(PixelResolved, x, y, fragments, r, g, b, a)
HSR_TO_JSON(ABufferFinished, fragments, pixels, longest_list, bounded)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::ABufferEvent)
}  // namespace hsr::viz
