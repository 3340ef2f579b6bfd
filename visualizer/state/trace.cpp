#include "state/trace.h"

#include <cstdio>

#include <nlohmann/json.hpp>

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

}  // namespace hsr::algo

namespace hsr::viz {

std::string trace_line(std::uint64_t step, const algo::ClipEvent& e, algo::ClipSpace s) {
    nlohmann::ordered_json j;
    j["step"] = step;
    j["kind"] = algo::kind_of(e);
    std::visit(
        [&](const auto& ev) {
            const nlohmann::json fields = ev;
            for (const auto& [key, value] : fields.items()) j[key] = value;
        },
        e);
    j["text"] = algo::describe(e, s);
    return j.dump();
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

}  // namespace hsr::viz
