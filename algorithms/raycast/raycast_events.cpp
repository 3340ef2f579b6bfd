// SPDX-License-Identifier: MIT
#include "raycast/raycast_events.h"

#include <algorithm>

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
constexpr Saying bvh{"ray_cast.bvh", "bounding-volume hierarchy"};
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
constexpr Saying examined{"ray_cast.examined",
                          "Cell {node} (depth {depth}, edge {edge}) lists {primitives} {primitives?primitive|primitives}."};
constexpr Saying split{"ray_cast.split", "Cell {node} is split into 8 subcells, {first} to {last}: {listed} primitives listed over them."};
constexpr Saying leaf_made{"ray_cast.leaf_made", "Cell {node} stays a leaf with {primitives} {primitives?primitive|primitives}: {reason}."};
constexpr Saying built{"ray_cast.built", "The octree is built: {nodes} cells, {leaves} leaves, {depth} levels below the root."};
constexpr Saying few_primitives{"ray_cast.few_primitives", "few enough primitives"};
constexpr Saying voxel_size{"ray_cast.voxel_size", "the voxel size is reached"};
constexpr Saying node_budget{"ray_cast.node_budget", "the node budget is spent"};
constexpr Saying would_multiply{"ray_cast.would_multiply", "its primitives would be listed in most subcells"};
constexpr Saying all[] = {every_primitive, grid, octree, bvh, started, cell, empty_cell, node, leaf, hit, missed, nearer, sees,
                          sees_background, done, bound, examined, split, leaf_made, built, few_primitives, voxel_size,
                          node_budget, would_multiply};
}  // namespace say
}  // namespace

const Saying& term(Acceleration a) {
    switch (a) {
        case Acceleration::none: return say::every_primitive;
        case Acceleration::grid: return say::grid;
        case Acceleration::octree: return say::octree;
        case Acceleration::bvh: return say::bvh;
    }
    return say::every_primitive;
}

std::string_view to_string(Acceleration a) { return term(a).english; }

const Saying& term(OctreeStop r) {
    switch (r) {
        case OctreeStop::few_primitives: return say::few_primitives;
        case OctreeStop::voxel_size: return say::voxel_size;
        case OctreeStop::node_budget: return say::node_budget;
        case OctreeStop::would_multiply: return say::would_multiply;
    }
    return say::few_primitives;
}

std::string_view to_string(OctreeStop r) { return term(r).english; }

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
            [](const OctreeCellExamined& e) {
                const glm::dvec3 size = e.hi - e.lo;
                return Phrase(say::examined, {{"node", n(std::uint64_t(e.node))}, {"depth", n(e.depth)},
                                              {"edge", format_number(std::max({size.x, size.y, size.z}))},
                                              {"primitives", n(std::uint64_t(e.primitives))}});
            },
            [](const OctreeCellSplit& e) {
                return Phrase(say::split, {{"node", n(std::uint64_t(e.node))}, {"first", n(std::uint64_t(e.first_child))},
                                           {"last", n(std::uint64_t(e.first_child) + 7)}, {"listed", n(std::uint64_t(e.listed))}});
            },
            [](const OctreeLeafMade& e) {
                return Phrase(say::leaf_made, {{"node", n(std::uint64_t(e.node))}, {"primitives", n(std::uint64_t(e.primitives))}},
                              Terms{{"reason", &term(e.reason)}});
            },
            [](const OctreeBuilt& e) {
                return Phrase(say::built, {{"nodes", n(std::uint64_t(e.nodes))}, {"leaves", n(std::uint64_t(e.leaves))}, {"depth", n(e.depth)}});
            },
        },
        event);
}

std::string describe(const RayCastEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
