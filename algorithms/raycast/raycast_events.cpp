// SPDX-License-Identifier: MIT
#include "raycast/raycast_events.h"

#include "core/events.h"
#include "core/overloaded.h"

namespace hsr::algo {
namespace {

std::string vec(const glm::dvec3& v) {
    return "(" + format_number(v.x) + ", " + format_number(v.y) + ", " + format_number(v.z) + ")";
}

}  // namespace

std::string_view to_string(Acceleration a) {
    switch (a) {
        case Acceleration::none: return "every primitive";
        case Acceleration::grid: return "regular grid";
        case Acceleration::octree: return "octree";
    }
    return "?";
}

std::string describe(const RayCastEvent& event) {
    return std::visit(
        overloaded{
            [](const RayStarted& e) {
                return "Ray through pixel (" + std::to_string(e.x) + ", " + std::to_string(e.y) + ") from " +
                       vec(e.origin) + ", direction " + vec(e.direction) + ".";
            },
            [](const CellEntered& e) {
                return "Enter cell [" + std::to_string(e.cell.x) + ", " + std::to_string(e.cell.y) + ", " +
                       std::to_string(e.cell.z) + "] for t in [" + format_number(e.t_enter) + ", " +
                       format_number(e.t_exit) + "]: " + std::to_string(e.primitives) + " primitives listed" +
                       (e.primitives == 0 ? ", skipped." : ".");
            },
            [](const NodeEntered& e) {
                return std::string(e.leaf ? "Enter leaf " : "Enter node ") + std::to_string(e.node) + " (depth " +
                       std::to_string(e.depth) + ") for t in [" + format_number(e.t_enter) + ", " +
                       format_number(e.t_exit) + "].";
            },
            [](const PrimitiveTested& e) {
                return "Test polygon " + std::to_string(e.id) + ": " +
                       (e.hit ? "hit at t = " + format_number(e.t) + "." : "missed.");
            },
            [](const NearerHitFound& e) {
                return "Nearest so far: polygon " + std::to_string(e.id) + " at t = " + format_number(e.t) + ".";
            },
            [](const RayFinished& e) {
                return "Pixel (" + std::to_string(e.x) + ", " + std::to_string(e.y) + ") sees " +
                       (e.index < 0 ? std::string("the background") : "polygon " + std::to_string(e.id)) + " after " +
                       std::to_string(e.tests) + " tests.";
            },
            [](const CastFinished& e) {
                return "Done: " + std::to_string(e.rays) + " rays, " + std::to_string(e.tests) + " primitive tests.";
            },
            [](const CastStepBoundReached& e) {
                return "Stopped: the step bound of " + std::to_string(e.max_tests) + " primitive tests was reached.";
            },
        },
        event);
}

}  // namespace hsr::algo
