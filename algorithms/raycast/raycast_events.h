// SPDX-License-Identifier: MIT
// What the ray caster tells as it runs: each ray, the grid cells or octree nodes it walks, each primitive it tests,
// each nearer hit, and the answer per pixel. t is the ray parameter: 0 on the near plane, 1 on the far plane.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include <glm/vec3.hpp>

#include "core/phrase.h"
#include "scene/scene.h"

namespace hsr::algo {

// bvh: a bounding-volume hierarchy of axis boxes over the primitives, walked nearest box first (the fourth way)
enum class Acceleration : std::uint8_t { none, grid, octree, bvh };
// How much a cast tells: each ray's answer only, also its cells or nodes, or every primitive test too.
enum class RayDetail : std::uint8_t { ray, cell, test };

struct RayStarted {
    static constexpr std::string_view kind = "RayStarted";
    int x, y;              // the pixel
    glm::dvec3 origin;     // on the near plane, world space
    glm::dvec3 direction;  // to the far plane (t = 1), world space
    bool operator==(const RayStarted&) const = default;
};
struct CellEntered {
    static constexpr std::string_view kind = "CellEntered";
    glm::ivec3 cell;        // grid indices
    double t_enter, t_exit;  // where the ray is inside it
    std::uint32_t primitives;  // how many primitives the cell lists
    bool operator==(const CellEntered&) const = default;
};
struct NodeEntered {
    static constexpr std::string_view kind = "NodeEntered";
    std::uint32_t node;      // index into the octree's nodes
    int depth;               // 0 for the root
    double t_enter, t_exit;
    bool leaf;
    bool operator==(const NodeEntered&) const = default;
};
struct PrimitiveTested {
    static constexpr std::string_view kind = "PrimitiveTested";
    std::uint32_t index;  // into the scene's polygons
    SceneId id;
    bool hit;
    double t;             // where, when hit
    bool operator==(const PrimitiveTested&) const = default;
};
struct NearerHitFound {
    static constexpr std::string_view kind = "NearerHitFound";
    std::uint32_t index;
    SceneId id;
    double t;
    bool operator==(const NearerHitFound&) const = default;
};
struct RayFinished {
    static constexpr std::string_view kind = "RayFinished";
    int x, y;
    std::int32_t index;  // the nearest primitive, −1 for none
    SceneId id;          // its scene id, 0 for background
    double t;
    std::uint32_t tests;  // primitives this ray tested
    bool operator==(const RayFinished&) const = default;
};
struct CastFinished {
    static constexpr std::string_view kind = "CastFinished";
    std::uint64_t rays, tests;
    bool operator==(const CastFinished&) const = default;
};
struct CastStepBoundReached {
    static constexpr std::string_view kind = "CastStepBoundReached";
    std::uint64_t max_tests;
    bool operator==(const CastStepBoundReached&) const = default;
};

// The octree's build, before the first ray ("Space Subdivision"): a cell examined, then split into 8 subcells or made
// a leaf, and why it stopped. The notes' two stopping rules are few_primitives ("the object complexity within a
// cell is below a certain limit") and voxel_size ("an elementary cell size (voxel) is reached"); the other two keep
// the build bounded: a node budget, and a cell whose primitives would each be listed in most of its children.
enum class OctreeStop : std::uint8_t { few_primitives, voxel_size, node_budget, would_multiply };
struct OctreeCellExamined {
    static constexpr std::string_view kind = "OctreeCellExamined";
    std::uint32_t node;  // index into the octree's nodes; 0 is the root
    int depth;
    glm::dvec3 lo, hi;   // the cell
    std::uint32_t primitives;  // listed in it
    bool operator==(const OctreeCellExamined&) const = default;
};
struct OctreeCellSplit {
    static constexpr std::string_view kind = "OctreeCellSplit";
    std::uint32_t node, first_child;  // the children are first_child … first_child + 7
    std::uint32_t listed;             // the primitives over the 8 children, each counted as often as it is listed
    bool operator==(const OctreeCellSplit&) const = default;
};
struct OctreeLeafMade {
    static constexpr std::string_view kind = "OctreeLeafMade";
    std::uint32_t node;
    OctreeStop reason;
    std::uint32_t primitives;
    double edge;  // the cell's longest edge, to set against the voxel size
    bool operator==(const OctreeLeafMade&) const = default;
};
struct OctreeBuilt {
    static constexpr std::string_view kind = "OctreeBuilt";
    std::uint32_t nodes, leaves;
    int depth;
    bool operator==(const OctreeBuilt&) const = default;
};

using RayCastEvent = std::variant<RayStarted, CellEntered, NodeEntered, PrimitiveTested, NearerHitFound, RayFinished,
                                  CastFinished, CastStepBoundReached, OctreeCellExamined, OctreeCellSplit, OctreeLeafMade,
                                  OctreeBuilt>;

// What an event says, as a template with named values (core/phrase.h), and in English.
Phrase phrase(const RayCastEvent& e);
std::string describe(const RayCastEvent& e);
const Saying& term(Acceleration a);  // "regular grid"
std::string_view to_string(Acceleration a);
const Saying& term(OctreeStop r);  // "at most 8 primitives"
std::string_view to_string(OctreeStop r);
std::span<const Saying> ray_cast_sayings();

}  // namespace hsr::algo
