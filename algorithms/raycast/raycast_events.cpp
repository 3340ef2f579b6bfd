// SPDX-License-Identifier: MIT
#include "raycast/raycast_events.h"

#include "core/events.h"
#include "core/overloaded.h"

namespace hsr::algo {
namespace {

std::string n(std::uint64_t v) { return std::to_string(v); }
std::string n(int v) { return std::to_string(v); }
std::string vec(const glm::dvec3& v) {
    return "(" + format_number(v.x) + ", " + format_number(v.y) + ", " + format_number(v.z) + ")";
}

// What the ray caster says, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying every_primitive{"ray_cast.every_primitive", "every primitive"};
constexpr Saying grid{"ray_cast.grid", "regular grid"};
constexpr Saying octree{"ray_cast.octree", "octree"};
constexpr Saying started{"ray_cast.started", "Ray through pixel ({x}, {y}) from {origin}, direction {direction}."};
constexpr Saying cell{"ray_cast.cell",
                      "Enter cell [{i}, {j}, {k}] for t in [{t_enter}, {t_exit}]: {primitives} {primitives?primitive|primitives} listed."};
constexpr Saying empty_cell{"ray_cast.empty_cell", "Enter cell [{i}, {j}, {k}] for t in [{t_enter}, {t_exit}]: 0 primitives listed, skipped."};
constexpr Saying node{"ray_cast.node", "Enter node {node} (depth {depth}) for t in [{t_enter}, {t_exit}]."};
constexpr Saying leaf{"ray_cast.leaf", "Enter leaf {node} (depth {depth}) for t in [{t_enter}, {t_exit}]."};
constexpr Saying hit{"ray_cast.hit", "Test polygon {polygon}: hit at t = {t}."};
constexpr Saying missed{"ray_cast.missed", "Test polygon {polygon}: missed."};
constexpr Saying nearer{"ray_cast.nearer", "Nearest so far: polygon {polygon} at t = {t}."};
constexpr Saying sees{"ray_cast.sees", "Pixel ({x}, {y}) sees polygon {polygon} after {tests} {tests?test|tests}."};
constexpr Saying sees_background{"ray_cast.sees_background", "Pixel ({x}, {y}) sees the background after {tests} {tests?test|tests}."};
constexpr Saying done{"ray_cast.done", "Done: {rays} {rays?ray|rays}, {tests} primitive {tests?test|tests}."};
constexpr Saying bound{"ray_cast.bound", "Stopped: the step bound of {tests} primitive tests was reached."};
constexpr Saying all[] = {every_primitive, grid, octree, started, cell, empty_cell, node, leaf, hit, missed, nearer, sees,
                          sees_background, done, bound};
}  // namespace say
}  // namespace

const Saying& term(Acceleration a) {
    switch (a) {
        case Acceleration::none: return say::every_primitive;
        case Acceleration::grid: return say::grid;
        case Acceleration::octree: return say::octree;
    }
    return say::every_primitive;
}

std::string_view to_string(Acceleration a) { return term(a).english; }

std::span<const Saying> ray_cast_sayings() { return say::all; }

Phrase phrase(const RayCastEvent& event) {
    return std::visit(
        overloaded{
            [](const RayStarted& e) {
                return Phrase(say::started, {{"x", n(e.x)}, {"y", n(e.y)}, {"origin", vec(e.origin)}, {"direction", vec(e.direction)}});
            },
            [](const CellEntered& e) {
                return Phrase(e.primitives == 0 ? say::empty_cell : say::cell,
                              {{"i", n(e.cell.x)}, {"j", n(e.cell.y)}, {"k", n(e.cell.z)}, {"t_enter", format_number(e.t_enter)},
                               {"t_exit", format_number(e.t_exit)}, {"primitives", n(std::uint64_t(e.primitives))}});
            },
            [](const NodeEntered& e) {
                return Phrase(e.leaf ? say::leaf : say::node,
                              {{"node", n(std::uint64_t(e.node))}, {"depth", n(e.depth)}, {"t_enter", format_number(e.t_enter)},
                               {"t_exit", format_number(e.t_exit)}});
            },
            [](const PrimitiveTested& e) {
                return Phrase(e.hit ? say::hit : say::missed, {{"polygon", n(e.id)}, {"t", format_number(e.t)}});
            },
            [](const NearerHitFound& e) {
                return Phrase(say::nearer, {{"polygon", n(e.id)}, {"t", format_number(e.t)}});
            },
            [](const RayFinished& e) {
                return Phrase(e.index < 0 ? say::sees_background : say::sees,
                              {{"x", n(e.x)}, {"y", n(e.y)}, {"polygon", n(e.id)}, {"tests", n(std::uint64_t(e.tests))}});
            },
            [](const CastFinished& e) { return Phrase(say::done, {{"rays", n(e.rays)}, {"tests", n(e.tests)}}); },
            [](const CastStepBoundReached& e) { return Phrase(say::bound, {{"tests", n(e.max_tests)}}); },
        },
        event);
}

std::string describe(const RayCastEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
