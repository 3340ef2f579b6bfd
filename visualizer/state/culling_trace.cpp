// SPDX-License-Identifier: MIT
// The trace's fields of the culling machines's events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "culling/hiz.h"
#include "culling/occluders.h"

namespace hsr::algo {

inline void to_json(nlohmann::json& j, const Aabb& b) { j = {{"lo", {b.lo.x, b.lo.y, b.lo.z}}, {"hi", {b.hi.x, b.hi.y, b.hi.z}}}; }
inline void to_json(nlohmann::json& j, const PixelRect& r) { j = nlohmann::json::array({r.x0, r.y0, r.x1, r.y1}); }
inline void to_json(nlohmann::json& j, LeafReason r) { j = std::string(to_string(r)); }
inline void to_json(nlohmann::json& j, NodeOutcome o) { j = std::string(to_string(o)); }
inline void to_json(nlohmann::json& j, OcclusionOutcome o) {
    j = o == OcclusionOutcome::occluded ? "occluded" : o == OcclusionOutcome::partly ? "partly" : "visible";
}
inline void to_json(nlohmann::json& j, HizOutcome o) {
    j = o == HizOutcome::outside_frustum ? "outside the frustum" : o == HizOutcome::occluded ? "occluded" : "rendered";
}
HSR_TO_JSON(HierarchyNodeBuilt, node, parent, depth, primitives, box, leaf)
HSR_TO_JSON(HierarchyBuilt, nodes, leaves, depth)
HSR_TO_JSON(NodeCulled, node, outcome, planes_tested, mask_after, plane, pixels, primitives, own_primitives, primitive_tests)
HSR_TO_JSON(HierarchyCullFinished, nodes_tested, plane_tests, kept, outside, too_small)
inline void to_json(nlohmann::json& j, OccluderKind k) { j = std::string(to_string(k)); }
HSR_TO_JSON(OccluderChosen, polygon, rank, area, shape, faces)
HSR_TO_JSON(OcclusionTested, node, primitive, outcome, occluder, fused)
HSR_TO_JSON(OcclusionFinished, occluders, culled, passed, fused)
HSR_TO_JSON(HizNodeTested, node, outcome, footprint, near, texels_tested, primitives_rendered, subtree_primitives)
HSR_TO_JSON(HizFinished, nodes, occluded_nodes, rendered, left_out)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::HierarchyEvent)
HSR_TRACE_LINES(algo::HierarchyCullEvent)
HSR_TRACE_LINES(algo::OcclusionEvent)
HSR_TRACE_LINES(algo::HizEvent)
}  // namespace hsr::viz
