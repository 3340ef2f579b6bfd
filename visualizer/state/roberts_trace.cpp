// SPDX-License-Identifier: MIT
// The trace's fields of Roberts' events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "roberts/roberts_events.h"

namespace hsr::algo {

HSR_TO_JSON(BodiesFound, bodies, edges)
HSR_TO_JSON(EdgeRemoved, edge, body)
HSR_TO_JSON(EdgeTested, edge, body, by, hides, t0, t1)
HSR_TO_JSON(EdgeFinished, edge, hidden, pieces)
HSR_TO_JSON(RobertsFinished, drawn, removed, tests, bounded)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::RobertsEvent)
}  // namespace hsr::viz
