// SPDX-License-Identifier: MIT
#include "culling/culling_events.h"

#include "core/events.h"
#include "core/overloaded.h"

namespace hsr::algo {
namespace {

std::string n(std::uint64_t v) { return std::to_string(v); }

}  // namespace

std::string_view to_string(NodeOutcome o) {
    switch (o) {
        case NodeOutcome::outside: return "outside";
        case NodeOutcome::inside: return "inside";
        case NodeOutcome::partial: return "partly inside";
        case NodeOutcome::too_small: return "too small";
    }
    return "?";
}

std::string_view to_string(LeafReason r) {
    switch (r) {
        case LeafReason::not_a_leaf: return "split";
        case LeafReason::few_primitives: return "a leaf: few primitives";
        case LeafReason::cell_size: return "a leaf: the smallest cell";
        case LeafReason::depth_bound: return "a leaf: the depth bound";
    }
    return "?";
}

std::string describe(const HierarchyEvent& event) {
    return std::visit(overloaded{
                          [](const HierarchyNodeBuilt& e) -> std::string {
                              return "Node " + n(e.node) + " at depth " + n(e.depth) + ": " + n(e.primitives) + " primitives, " +
                                     std::string(to_string(e.leaf)) + ".";
                          },
                          [](const HierarchyBuilt& e) -> std::string {
                              return "Built: " + n(e.nodes) + " nodes, " + n(e.leaves) + " leaves, " + n(e.depth) + " levels.";
                          },
                      },
                      event);
}

std::string describe(const HierarchyCullEvent& event) {
    return std::visit(
        overloaded{
            [](const NodeCulled& e) -> std::string {
                std::string s = "Node " + n(e.node) + " (" + n(e.primitives) + " primitives): " + std::string(to_string(e.outcome));
                if (e.outcome == NodeOutcome::outside) s += " plane " + n(std::uint64_t(e.plane));
                if (e.outcome == NodeOutcome::too_small) s += " (" + format_number(e.pixels) + " pixels)";
                return s + " after " + n(e.planes_tested) + (e.planes_tested == 1 ? " plane test." : " plane tests.");
            },
            [](const HierarchyCullFinished& e) -> std::string {
                return "Done: " + n(e.nodes_tested) + " nodes, " + n(e.plane_tests) + " plane tests; " + n(e.kept) + " primitives kept, " +
                       n(e.outside) + " outside, " + n(e.too_small) + " too small.";
            },
        },
        event);
}

}  // namespace hsr::algo
