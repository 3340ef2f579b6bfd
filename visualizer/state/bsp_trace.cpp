// SPDX-License-Identifier: MIT
// The trace's fields of BSP build and traversal's events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "bsp/bsp_events.h"

namespace hsr::algo {

inline void to_json(nlohmann::json& j, SplitterRule r) { j = std::string(to_string(r)); }
inline void to_json(nlohmann::json& j, BspBound b) { j = std::string(to_string(b)); }
inline void to_json(nlohmann::json& j, Order o) { j = o == Order::back_to_front ? "back to front" : "front to back"; }

// A shared vertex list is written as its vertices (written by hand: ADL does not look in hsr::algo for a
// std::shared_ptr, so the field macro cannot find a to_json for it).
inline nlohmann::json vertices_json(const VertexList& v) {
    nlohmann::json j = nlohmann::json::array();
    if (v)
        for (const Vec3& x : *v) j.push_back({x.x, x.y, x.z});
    return j;
}
inline void to_json(nlohmann::json& j, const PolygonSplit& e) {
    j = {{"node", e.node}, {"polygon", e.polygon}, {"front_part", e.front_part}, {"back_part", e.back_part},
         {"front", vertices_json(e.front)}, {"back", vertices_json(e.back)}};
}

HSR_TO_JSON(BuildStarted, polygons, rule, tolerance)
HSR_TO_JSON(CandidateScored, node, candidate, front, back, spanning, score)
HSR_TO_JSON(SplitterChosen, node, parent, side, splitter, depth, candidates, score, plane)
HSR_TO_JSON(PolygonClassified, node, polygon, side, splitter)
HSR_TO_JSON(NodeFinished, node, coplanar, front, back, splitter)
HSR_TO_JSON(BuildFinished, nodes, depth, polygons, splits)
HSR_TO_JSON(EyeClassified, node, side, order, distance, splitter)
HSR_TO_JSON(PolygonDrawn, node, polygon, order, eye_side, leaf)
HSR_TO_JSON(TraversalFinished, drawn)
HSR_TO_JSON(BspBoundReached, bound, limit)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::BspEvent)
}  // namespace hsr::viz
