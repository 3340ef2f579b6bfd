// SPDX-License-Identifier: MIT
// The trace's fields of the general forms' events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "forms/forms_events.h"

namespace hsr::algo {

HSR_TO_JSON(FormsShown, primitives, pixels, perspective)
HSR_TO_JSON(PrimitiveProjected, primitive, id, in_view, from, to)
HSR_TO_JSON(PrimitivesCompared, primitive, other, id, other_id, overlap, hides, hidden_from, hidden_to)
HSR_TO_JSON(VisiblePartFound, primitive, id, parts, share)
HSR_TO_JSON(PartRendered, primitive, id, pixels)
HSR_TO_JSON(ProjectorTested, pixel, primitive, id, hit, depth, closest)
HSR_TO_JSON(PixelRendered, pixel, primitive, id, depth)
HSR_TO_JSON(FormsFinished, primitives, in_view, pixels, comparisons, tests, differing, bounded)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::FormsEvent)
}  // namespace hsr::viz
