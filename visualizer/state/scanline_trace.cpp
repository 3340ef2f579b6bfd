// SPDX-License-Identifier: MIT
// The trace's fields of the scan line's events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "zbuffer/scanline_events.h"

namespace hsr::algo {

HSR_TO_JSON(EdgeTableBuilt, edges, polygons)
HSR_TO_JSON(ScanLineStarted, y)
HSR_TO_JSON(EdgeEntered, edge, polygon, y, x)
HSR_TO_JSON(EdgeLeft, edge, polygon, y)
HSR_TO_JSON(EdgeCrossed, edge, polygon, y, x, entering)
HSR_TO_JSON(DepthsCompared, y, x, in, nearest, depth, next, next_depth)
HSR_TO_JSON(PiercingFound, y, x, was, now, pixel)
HSR_TO_JSON(SpanColored, y, x_begin, x_end, polygon, id)
HSR_TO_JSON(ScanFinished, lines, spans)
HSR_TO_JSON(ScanStepBoundReached, max_crossings)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::ScanLineEvent)
}  // namespace hsr::viz
