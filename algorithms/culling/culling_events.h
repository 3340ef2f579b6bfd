// SPDX-License-Identifier: MIT
// What the culling machines tell: a hierarchy built node by node (BVH or octree), and a hierarchy culled top-down
// against the view frustum and for detail, each node's outcome with the planes it took to decide.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <span>
#include <variant>

#include "core/phrase.h"
#include "culling/bounding_volume.h"

namespace hsr::algo {

enum class LeafReason : std::uint8_t { not_a_leaf, few_primitives, cell_size, depth_bound };

struct HierarchyNodeBuilt {
    static constexpr std::string_view kind = "HierarchyNodeBuilt";
    std::uint32_t node;
    std::int32_t parent;
    std::uint32_t depth, primitives;  // primitives: in its whole subtree
    Aabb box;
    LeafReason leaf;
    bool operator==(const HierarchyNodeBuilt&) const = default;
};
struct HierarchyBuilt {
    static constexpr std::string_view kind = "HierarchyBuilt";
    std::uint32_t nodes, leaves, depth;
    bool operator==(const HierarchyBuilt&) const = default;
};
using HierarchyEvent = std::variant<HierarchyNodeBuilt, HierarchyBuilt>;

// The visibility test of a node's box against the planes of the view frustum, and detail culling.
enum class NodeOutcome : std::uint8_t {
    outside,       // wholly outside a plane: rejected with everything below it
    inside,        // wholly inside every plane still to test: accepted with everything below it, no more tests
    partial,       // crosses a plane: its primitives are kept, its children tested
    too_small,     // its projected size is below the detail threshold: left out with everything below it
    large_enough,  // detail culling alone (no frustum): not below the threshold, its primitives kept, its children tested
};
struct NodeCulled {
    static constexpr std::string_view kind = "NodeCulled";
    std::uint32_t node;
    NodeOutcome outcome;
    std::uint8_t planes_tested;  // planes this node was tested against (those its parent was not wholly inside)
    std::uint8_t mask_after;     // planes its children must still test (bit k: plane k)
    std::int8_t plane;           // outside: the plane that rejected it; else −1
    double pixels;               // its projected size (detail culling on), else 0
    std::uint32_t primitives;    // in its subtree
    std::uint32_t own_primitives = 0;   // partial: the primitives it holds itself (not its children), reaching this stage
    std::uint32_t primitive_tests = 0;  // partial: plane tests of those primitives' boxes against the planes still to test
    bool operator==(const NodeCulled&) const = default;
};
struct HierarchyCullFinished {
    static constexpr std::string_view kind = "HierarchyCullFinished";
    // plane_tests: every one, the nodes' (planes_tested) and their own primitives' boxes' (primitive_tests)
    std::uint32_t nodes_tested, plane_tests, kept, outside, too_small;  // kept / left out: primitives
    bool operator==(const HierarchyCullFinished&) const = default;
};
using HierarchyCullEvent = std::variant<NodeCulled, HierarchyCullFinished>;

// What an event says, as a template with named values (core/phrase.h), and in English.
Phrase phrase(const HierarchyEvent& e);
Phrase phrase(const HierarchyCullEvent& e);
std::string describe(const HierarchyEvent& e);
std::string describe(const HierarchyCullEvent& e);
std::string_view to_string(NodeOutcome o);
std::string_view to_string(LeafReason r);
const Saying& term(NodeOutcome o);  // words to translate
const Saying& term(LeafReason r);
std::span<const Saying> culling_sayings();  // every template the hierarchy's build and cull say

}  // namespace hsr::algo
