// SPDX-License-Identifier: MIT
// How an event becomes a trace line: the JSON of its fields, written by each family's <family>_trace.cpp with
// HSR_TO_JSON, which then instantiates trace_line for its event variants with HSR_TRACE_LINES. Only those files
// include this one (nlohmann's macros stay out of every other translation unit).
#pragma once

#include <cstdint>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "core/events.h"
#include "core/plane.h"
#include "state/trace.h"

namespace glm {
// Points are written as [x, y, z, w], [x, y, z] or [x, y].
inline void to_json(nlohmann::json& j, const dvec4& v) { j = nlohmann::json::array({v.x, v.y, v.z, v.w}); }
inline void to_json(nlohmann::json& j, const dvec3& v) { j = nlohmann::json::array({v.x, v.y, v.z}); }
inline void to_json(nlohmann::json& j, const ivec3& v) { j = nlohmann::json::array({v.x, v.y, v.z}); }
inline void to_json(nlohmann::json& j, const dvec2& v) { j = nlohmann::json::array({v.x, v.y}); }
}  // namespace glm

namespace hsr::algo {
inline void to_json(nlohmann::json& j, Side s) { j = std::string(to_string(s)); }
inline void to_json(nlohmann::json& j, PolygonSide s) { j = std::string(to_string(s)); }
inline void to_json(nlohmann::json& j, const Plane& p) { j = nlohmann::json::array({p.n.x, p.n.y, p.n.z, p.d}); }
}  // namespace hsr::algo

// Writes the named fields of an event; events are only ever written, so no from_json is made.
#define HSR_TO_JSON(Type, ...)                                                            \
    inline void to_json(nlohmann::json& nlohmann_json_j, const Type& nlohmann_json_t) { \
        NLOHMANN_JSON_EXPAND(NLOHMANN_JSON_PASTE(NLOHMANN_JSON_TO, __VA_ARGS__))          \
    }

namespace hsr::viz {

template <class Event>
std::string trace_line(std::uint64_t step, const Event& e, const std::string& sentence) {
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

}  // namespace hsr::viz

// trace_line for an event variant, made where its fields' to_json are in sight.
#define HSR_TRACE_LINES(EventVariant) \
    template std::string trace_line<EventVariant>(std::uint64_t, const EventVariant&, const std::string&);
