// SPDX-License-Identifier: MIT
// The trace's fields of clipping's events (one JSON object per event: state/trace.h).
#include "state/trace_json.h"

#include "clipping/clip_events.h"

namespace hsr::algo {

inline void to_json(nlohmann::json& j, const Outcode& c) { j = to_string(c); }
inline void to_json(nlohmann::json& j, ClipPlane p) { j = std::string(plane_name(p)); }
inline void to_json(nlohmann::json& j, Endpoint e) { j = e == Endpoint::p1 ? "p1" : "p2"; }
inline void to_json(nlohmann::json& j, ClipOutcome o) { j = std::string(to_string(o)); }
inline void to_json(nlohmann::json& j, EdgeCase c) { j = std::string(to_string(c)); }
inline void to_json(nlohmann::json& j, BoundaryCase c) { j = std::string(to_string(c)); }
inline void to_json(nlohmann::json& j, Bound b) { j = std::string(to_string(b)); }
inline void to_json(nlohmann::json& j, Parameter p) { j = p == Parameter::t_enter ? "t_enter" : "t_leave"; }

HSR_TO_JSON(PointClassified, id, code, p)
HSR_TO_JSON(SegmentStarted, id, p1, p2)
HSR_TO_JSON(OutcodeComputed, endpoint, code, round, p)
HSR_TO_JSON(CodesCompared, c1, c2)
HSR_TO_JSON(TriviallyAccepted, c1, c2)
HSR_TO_JSON(TriviallyRejected, c1, c2)
HSR_TO_JSON(PlaneChosen, plane, outside)
HSR_TO_JSON(IntersectionComputed, plane, replaces, t, point)
HSR_TO_JSON(BoundaryTested, plane, how, p, q)
HSR_TO_JSON(ParameterUpdated, which, before, after)
HSR_TO_JSON(SegmentEmptied, plane, t_enter, t_leave)
HSR_TO_JSON(SegmentFinished, id, outcome, a, b)
HSR_TO_JSON(PolygonStarted, id, vertices)
HSR_TO_JSON(StageStarted, plane, input_vertices)
HSR_TO_JSON(EdgeClassified, plane, edge_case, closes, from, bc_from, bc_to, intersection)
HSR_TO_JSON(StageFinished, plane, output_vertices)
HSR_TO_JSON(PolygonFinished, id, outcome, vertices)
HSR_TO_JSON(StepBoundReached, bound, limit)

}  // namespace hsr::algo

namespace hsr::viz {
HSR_TRACE_LINES(algo::ClipEvent)
}  // namespace hsr::viz
