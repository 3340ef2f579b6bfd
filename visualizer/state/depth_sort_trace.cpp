// SPDX-License-Identifier: MIT
// The trace's fields of depth sort's events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "depth_sort/depth_sort_events.h"

namespace hsr::algo {

inline void to_json(nlohmann::json& j, OrderTest t) { j = std::string(to_string(t)); }
inline void to_json(nlohmann::json& j, SortBound b) { j = b == SortBound::splits ? "splits" : "pairs"; }
HSR_TO_JSON(ListSorted, order)
HSR_TO_JSON(PairExamined, r, q, r_min_z, r_max_z, q_min_z, q_max_z)
HSR_TO_JSON(TestTried, test, passed, a, b, c, d)
HSR_TO_JSON(PolygonMoved, polygon, ahead_of)
HSR_TO_JSON(CycleDetected, polygon)
HSR_TO_JSON(PolygonCut, polygon, by, front, back, front_vertices, back_vertices, across)
HSR_TO_JSON(PolygonPainted, polygon, id)
HSR_TO_JSON(DepthSortFinished, drawn, splits, moves, pairs)
HSR_TO_JSON(SortBoundReached, bound, limit)
HSR_TO_JSON(FrontPolygonDrawn, polygon, id, written, hidden, unwritten)
HSR_TO_JSON(ScreenFilled, drawn, left)
HSR_TO_JSON(FrontDisplayFinished, drawn, unwritten)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::DepthSortEvent)
}  // namespace hsr::viz
