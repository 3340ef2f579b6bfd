#include "state/trace.h"

#include <cstdio>

#include <nlohmann/json.hpp>

#include "state/families.h"

namespace glm {
// Points are written as [x, y, z, w].
inline void to_json(nlohmann::json& j, const dvec4& v) { j = nlohmann::json::array({v.x, v.y, v.z, v.w}); }
}  // namespace glm

// Writes the named fields of an event; events are only ever written, so no from_json is made.
#define HSR_TO_JSON(Type, ...)                                                            \
    inline void to_json(nlohmann::json& nlohmann_json_j, const Type& nlohmann_json_t) { \
        NLOHMANN_JSON_EXPAND(NLOHMANN_JSON_PASTE(NLOHMANN_JSON_TO, __VA_ARGS__))          \
    }

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

inline void to_json(nlohmann::json& j, ScreenStatus s) {
    j = s == ScreenStatus::drawn ? "drawn" : s == ScreenStatus::outside_view ? "outside view" : "zero area";
}
HSR_TO_JSON(BufferCleared, width, height, far_code)
HSR_TO_JSON(PolygonFillStarted, index, id, per_x)
HSR_TO_JSON(PolygonSkipped, index, id, why)
HSR_TO_JSON(SpanStarted, index, y, x_begin, x_end, depth)
HSR_TO_JSON(PixelTested, x, y, depth, incoming, stored, passes)
HSR_TO_JSON(DepthWritten, x, y, index, old_index, old_code, new_code)
HSR_TO_JSON(DepthTestFailed, x, y, incoming, stored)
HSR_TO_JSON(PolygonFillFinished, index, tested, written)
HSR_TO_JSON(FillFinished, polygons, tested, written)
HSR_TO_JSON(FillStepBoundReached, max_pixel_tests)

}  // namespace hsr::algo
namespace glm {
inline void to_json(nlohmann::json& j, const dvec3& v) { j = nlohmann::json::array({v.x, v.y, v.z}); }
inline void to_json(nlohmann::json& j, const ivec3& v) { j = nlohmann::json::array({v.x, v.y, v.z}); }
inline void to_json(nlohmann::json& j, const dvec2& v) { j = nlohmann::json::array({v.x, v.y}); }
}  // namespace glm
namespace hsr::algo {
HSR_TO_JSON(RayStarted, x, y, origin, direction)
HSR_TO_JSON(CellEntered, cell, t_enter, t_exit, primitives)
HSR_TO_JSON(NodeEntered, node, depth, t_enter, t_exit, leaf)
HSR_TO_JSON(PrimitiveTested, index, id, hit, t)
HSR_TO_JSON(NearerHitFound, index, id, t)
HSR_TO_JSON(RayFinished, x, y, index, id, t, tests)
HSR_TO_JSON(CastFinished, rays, tests)
HSR_TO_JSON(CastStepBoundReached, max_tests)
HSR_TO_JSON(EdgeTableBuilt, edges, polygons)
HSR_TO_JSON(ScanLineStarted, y)
HSR_TO_JSON(EdgeEntered, edge, polygon, y, x)
HSR_TO_JSON(EdgeLeft, edge, polygon, y)
HSR_TO_JSON(EdgeCrossed, edge, polygon, y, x, entering)
HSR_TO_JSON(SpanColored, y, x_begin, x_end, polygon, id)
HSR_TO_JSON(ScanFinished, lines, spans)
HSR_TO_JSON(ScanStepBoundReached, max_crossings)
HSR_TO_JSON(PixelMerged, x, y, depth_a, depth_b, from_a)
HSR_TO_JSON(MergeFinished, from_a, from_b)
inline void to_json(nlohmann::json& j, OrderTest t) { j = std::string(to_string(t)); }
inline void to_json(nlohmann::json& j, SortBound b) { j = b == SortBound::splits ? "splits" : "pairs"; }
HSR_TO_JSON(ListSorted, order)
HSR_TO_JSON(PairExamined, r, q, r_min_z, r_max_z, q_min_z, q_max_z)
HSR_TO_JSON(TestTried, test, passed, a, b, c, d)
HSR_TO_JSON(PolygonMoved, polygon, ahead_of)
HSR_TO_JSON(CycleDetected, polygon)
HSR_TO_JSON(PolygonCut, polygon, by, front, back, front_vertices, back_vertices)
HSR_TO_JSON(PolygonPainted, polygon, id)
HSR_TO_JSON(DepthSortFinished, drawn, splits, moves, pairs)
HSR_TO_JSON(SortBoundReached, bound, limit)

inline void to_json(nlohmann::json& j, Side s) { j = std::string(to_string(s)); }
inline void to_json(nlohmann::json& j, PolygonSide s) { j = std::string(to_string(s)); }
inline void to_json(nlohmann::json& j, SplitterRule r) { j = std::string(to_string(r)); }
inline void to_json(nlohmann::json& j, BspBound b) { j = std::string(to_string(b)); }
inline void to_json(nlohmann::json& j, Order o) { j = o == Order::back_to_front ? "back to front" : "front to back"; }
inline void to_json(nlohmann::json& j, const Plane& p) { j = nlohmann::json::array({p.n.x, p.n.y, p.n.z, p.d}); }

HSR_TO_JSON(StabTreeStarted, cell)
HSR_TO_JSON(SightlineTested, source, portals, found, line_space_area, point, direction, blocked_in_3d)
HSR_TO_JSON(CellReached, source, cell, depth, node, parent, portal)
HSR_TO_JSON(StabBoundReached, source, cell, limit, cells_assumed)
HSR_TO_JSON(PvsBuilt, cells, visible_pairs, sightline_tests)
inline void to_json(nlohmann::json& j, PortalVerdict v) { j = std::string(to_string(v)); }
inline void to_json(nlohmann::json& j, CullReason r) { j = std::string(to_string(r)); }
HSR_TO_JSON(EyeLocated, cell, path)
HSR_TO_JSON(PvsRowRead, cell, visible)
HSR_TO_JSON(CellVisited, cell, depth, frustum)
HSR_TO_JSON(PortalTested, portal, verdict, visible_part, narrowed)
HSR_TO_JSON(CellPolygonCulled, polygon, reason)
HSR_TO_JSON(CellPolygonDrawn, polygon, visible_part)
HSR_TO_JSON(PortalBoundReached, cell, limit)
HSR_TO_JSON(PortalRenderFinished, visits, drawn, culled_back_face, culled_frustum, portals_passed)

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
HSR_TO_JSON(NodeCulled, node, outcome, planes_tested, mask_after, plane, pixels, primitives)
HSR_TO_JSON(HierarchyCullFinished, nodes_tested, plane_tests, kept, outside, too_small)
HSR_TO_JSON(OccluderChosen, polygon, rank, area)
HSR_TO_JSON(OcclusionTested, node, primitive, outcome, occluder)
HSR_TO_JSON(OcclusionFinished, occluders, culled, passed)
HSR_TO_JSON(HizNodeTested, node, outcome, footprint, near, texels_tested, primitives_rendered, subtree_primitives)
HSR_TO_JSON(HizFinished, nodes, occluded_nodes, rendered, left_out)
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

inline void to_json(nlohmann::json& j, BackfaceTest t) { j = std::string(to_string(t)); }
inline void to_json(nlohmann::json& j, Facing f) { j = std::string(to_string(f)); }
HSR_TO_JSON(FaceTested, id, test, facing, value)
HSR_TO_JSON(CullingFinished, tested, culled)

HSR_TO_JSON(BuildStarted, polygons, rule, tolerance)
HSR_TO_JSON(CandidateScored, node, candidate, front, back, spanning, score)
HSR_TO_JSON(SplitterChosen, node, parent, side, splitter, depth, candidates, score, plane)
HSR_TO_JSON(PolygonClassified, node, polygon, side)
HSR_TO_JSON(NodeFinished, node, coplanar, front, back)
HSR_TO_JSON(BuildFinished, nodes, depth, polygons, splits)
HSR_TO_JSON(EyeClassified, node, side, order, distance)
HSR_TO_JSON(PolygonDrawn, node, polygon, order, eye_side, leaf)
HSR_TO_JSON(TraversalFinished, drawn)
HSR_TO_JSON(BspBoundReached, bound, limit)

}  // namespace hsr::algo

namespace hsr::viz {
namespace {

template <class Event>
std::string line_of(std::uint64_t step, const Event& e, const std::string& sentence) {
    nlohmann::ordered_json j;
    j["step"] = step;
    j["kind"] = algo::kind_of(e);
    std::visit(
        [&](const auto& ev) {
            const nlohmann::json fields = ev;
            for (const auto& [key, value] : fields.items()) j[key] = value;
        },
        e);
    j["text"] = sentence;
    return j.dump();
}

}  // namespace

std::string trace_line(std::uint64_t step, const algo::ClipEvent& e, const std::string& sentence) {
    return line_of(step, e, sentence);
}
std::string trace_line(std::uint64_t step, const algo::BspEvent& e, const std::string& sentence) {
    return line_of(step, e, sentence);
}
std::string trace_line(std::uint64_t step, const algo::CullEvent& e, const std::string& sentence) {
    return line_of(step, e, sentence);
}
std::string trace_line(std::uint64_t step, const algo::ZBufferEvent& e, const std::string& sentence) {
    return line_of(step, e, sentence);
}
std::string trace_line(std::uint64_t step, const algo::RayCastEvent& e, const std::string& sentence) {
    return line_of(step, e, sentence);
}
std::string trace_line(std::uint64_t step, const algo::ScanLineEvent& e, const std::string& sentence) {
    return line_of(step, e, sentence);
}
std::string trace_line(std::uint64_t step, const algo::ZMergeEvent& e, const std::string& sentence) {
    return line_of(step, e, sentence);
}
std::string trace_line(std::uint64_t step, const algo::HierarchyEvent& e, const std::string& sentence) {
    return line_of(step, e, sentence);
}
std::string trace_line(std::uint64_t step, const algo::HierarchyCullEvent& e, const std::string& sentence) {
    return line_of(step, e, sentence);
}
std::string trace_line(std::uint64_t step, const algo::OcclusionEvent& e, const std::string& sentence) {
    return line_of(step, e, sentence);
}
std::string trace_line(std::uint64_t step, const algo::HizEvent& e, const std::string& sentence) {
    return line_of(step, e, sentence);
}
std::string trace_line(std::uint64_t step, const algo::PvsEvent& e, const std::string& sentence) {
    return line_of(step, e, sentence);
}
std::string trace_line(std::uint64_t step, const algo::PortalEvent& e, const std::string& sentence) {
    return line_of(step, e, sentence);
}
std::string trace_line(std::uint64_t step, const algo::DepthSortEvent& e, const std::string& sentence) {
    return line_of(step, e, sentence);
}

void hash_line(TraceSummary& t, const std::string& line) {
    auto mix = [&](unsigned char c) {
        t.hash ^= c;
        t.hash *= 1099511628211ull;  // FNV-1a 64-bit prime
    };
    for (char c : line) mix(static_cast<unsigned char>(c));
    mix('\n');
}

std::string hex(std::uint64_t hash) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash));
    return buf;
}

namespace {
template <class V>
struct KindsOf;
template <class... E>
struct KindsOf<std::variant<E...>> {
    static std::vector<std::string> list() { return {std::string(E::kind)...}; }
};
}  // namespace

std::vector<std::string> event_kinds(const Lesson& lesson) {
    return with_family(lesson.algorithm, [](auto family) {
        return KindsOf<typename decltype(family)::Session::EventType>::list();
    });
}

TraceSummary trace_lesson(const Lesson& lesson, std::ostream* out) {
    return with_family(lesson.algorithm, [&](auto family) {
        using S = typename decltype(family)::Session;
        // the machine the window plays, its view folded alongside so that sentences name things as the window does
        auto run = S::machine(lesson);
        return write_trace(
            run.machine,
            [&](const auto& e) {
                reduce(run.initial, e);
                return S::sentence_of(e, run.initial);
            },
            out);
    });
}

}  // namespace hsr::viz
