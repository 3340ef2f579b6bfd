// SPDX-License-Identifier: MIT
// The trace's fields of ray casting's events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "raycast/raycast_events.h"

namespace hsr::algo {

inline void to_json(nlohmann::json& j, OctreeStop r) { j = std::string(to_string(r)); }

HSR_TO_JSON(RayStarted, x, y, origin, direction)
HSR_TO_JSON(CellEntered, cell, t_enter, t_exit, primitives)
HSR_TO_JSON(NodeEntered, node, depth, t_enter, t_exit, leaf)
HSR_TO_JSON(PrimitiveTested, index, id, hit, t)
HSR_TO_JSON(NearerHitFound, index, id, t)
HSR_TO_JSON(RayFinished, x, y, index, id, t, tests)
HSR_TO_JSON(CastFinished, rays, tests)
HSR_TO_JSON(CastStepBoundReached, max_tests)
HSR_TO_JSON(OctreeCellExamined, node, depth, lo, hi, primitives)
HSR_TO_JSON(OctreeCellSplit, node, first_child, listed)
HSR_TO_JSON(OctreeLeafMade, node, reason, primitives, edge)
HSR_TO_JSON(OctreeBuilt, nodes, leaves, depth)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::RayCastEvent)
}  // namespace hsr::viz
