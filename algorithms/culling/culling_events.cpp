// SPDX-License-Identifier: MIT
#include "culling/culling_events.h"

#include <cmath>
#include <cstdio>

#include "core/events.h"
#include "core/overloaded.h"
#include "core/phrase.h"

namespace hsr::algo {
namespace {

std::string n(std::uint64_t v) { return std::to_string(v); }
// a projected size as the lessons give it, 5.8 pixels (format_number would say 5.76788)
std::string one_decimal(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", v);
    return text;
}

}  // namespace

namespace {
// What the hierarchy's build and cull say, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying outside{"culling.outside", "outside"};
constexpr Saying inside{"culling.inside", "inside"};
constexpr Saying partial{"culling.partial", "partly inside"};
constexpr Saying too_small{"culling.too_small", "too small"};
constexpr Saying large_enough{"culling.large_enough", "large enough"};
constexpr Saying split{"culling.split", "split"};
constexpr Saying few_primitives{"culling.few_primitives", "a leaf: few primitives"};
constexpr Saying cell_size{"culling.cell_size", "a leaf: the smallest cell"};
constexpr Saying depth_bound{"culling.depth_bound", "a leaf: the depth bound"};
constexpr Saying node_built{"culling.node_built", "Node {node} at depth {depth}: {primitives} primitives, {leaf}."};
constexpr Saying built{"culling.built", "Built: {nodes} nodes, {leaves} leaves, {depth} levels."};
constexpr Saying node{"culling.node",
                      "Node {node} ({primitives} primitives): {outcome} after {tests} {tests?plane test|plane tests}."};
constexpr Saying node_outside{"culling.node_outside",
                              "Node {node} ({primitives} primitives): {outcome} plane {plane} after {tests} {tests?plane test|plane tests}."};
constexpr Saying node_own{"culling.node_own",
                          "Node {node} ({primitives} primitives): {outcome} after {tests} {tests?plane test|plane tests}, and "
                          "{own_tests} more for the boxes of the {own} {own?primitive|primitives} it holds itself."};
constexpr Saying node_too_small{"culling.node_too_small",
                                "Node {node} ({primitives} primitives): {outcome} ({pixels} pixels) after {tests} {tests?plane test|plane tests}."};
constexpr Saying node_detail_small{"culling.node_detail_small",
                                   "Node {node} ({primitives} primitives): {pixels} pixels, below the threshold: {outcome}, left out with all it holds."};
constexpr Saying node_detail_near{"culling.node_detail_near",
                                  "Node {node} ({primitives} primitives): its bounding sphere reaches the eye's plane, so it has no "
                                  "size on the screen to compare: {outcome}, its children are tested."};
constexpr Saying node_detail_large{"culling.node_detail_large",
                                   "Node {node} ({primitives} primitives): {pixels} pixels, not below the threshold: {outcome}, its children are tested."};
constexpr Saying done{"culling.done",
                      "Done: {nodes} nodes, {tests} plane tests; {kept} primitives kept, {outside} outside, {too_small} too small."};
constexpr Saying done_detail{"culling.done_detail", "Done: {nodes} nodes; {kept} primitives kept, {too_small} too small."};
constexpr Saying all[] = {outside,    inside,    partial, too_small,      large_enough,      split,
                          few_primitives, cell_size, depth_bound, node_built, built, node, node_own, node_outside,
                          node_too_small, node_detail_small, node_detail_near, node_detail_large, done, done_detail};
}  // namespace say
}  // namespace

const Saying& term(NodeOutcome o) {
    switch (o) {
        case NodeOutcome::outside: return say::outside;
        case NodeOutcome::inside: return say::inside;
        case NodeOutcome::partial: return say::partial;
        case NodeOutcome::too_small: return say::too_small;
        case NodeOutcome::large_enough: return say::large_enough;
    }
    return say::inside;
}

const Saying& term(LeafReason r) {
    switch (r) {
        case LeafReason::not_a_leaf: return say::split;
        case LeafReason::few_primitives: return say::few_primitives;
        case LeafReason::cell_size: return say::cell_size;
        case LeafReason::depth_bound: return say::depth_bound;
    }
    return say::split;
}

std::string_view to_string(NodeOutcome o) { return term(o).english; }
std::string_view to_string(LeafReason r) { return term(r).english; }

std::span<const Saying> culling_sayings() { return say::all; }

Phrase phrase(const HierarchyEvent& event) {
    return std::visit(overloaded{
                          [](const HierarchyNodeBuilt& e) {
                              return Phrase(say::node_built, {{"node", n(e.node)}, {"depth", n(e.depth)}, {"primitives", n(e.primitives)}},
                                            Terms{{"leaf", &term(e.leaf)}});
                          },
                          [](const HierarchyBuilt& e) {
                              return Phrase(say::built, {{"nodes", n(e.nodes)}, {"leaves", n(e.leaves)}, {"depth", n(e.depth)}});
                          },
                      },
                      event);
}

Phrase phrase(const HierarchyCullEvent& event) {
    return std::visit(
        overloaded{
            [](const NodeCulled& e) {
                // detail culling alone tests no plane: its sentences give the size, not a count of plane tests
                const bool detail_only = e.planes_tested == 0 && (e.outcome == NodeOutcome::too_small || e.outcome == NodeOutcome::large_enough);
                const Saying& saying = e.outcome == NodeOutcome::outside       ? say::node_outside
                                       : detail_only && e.outcome == NodeOutcome::too_small ? say::node_detail_small
                                       : detail_only && !std::isfinite(e.pixels) ? say::node_detail_near
                                       : detail_only                           ? say::node_detail_large
                                       : e.outcome == NodeOutcome::too_small   ? say::node_too_small
                                       : e.primitive_tests > 0                 ? say::node_own
                                                                               : say::node;
                return Phrase(saying,
                              {{"node", n(e.node)}, {"primitives", n(e.primitives)}, {"plane", n(std::uint64_t(e.plane))},
                               {"pixels", one_decimal(e.pixels)}, {"tests", n(e.planes_tested)}, {"own", n(e.own_primitives)},
                               {"own_tests", n(e.primitive_tests)}},
                              Terms{{"outcome", &term(e.outcome)}});
            },
            [](const HierarchyCullFinished& e) {
                // detail culling alone: no plane was tested, nothing was outside
                return Phrase(e.plane_tests == 0 && e.outside == 0 && e.too_small > 0 ? say::done_detail : say::done, {{"nodes", n(e.nodes_tested)}, {"tests", n(e.plane_tests)}, {"kept", n(e.kept)},
                                          {"outside", n(e.outside)}, {"too_small", n(e.too_small)}});
            },
        },
        event);
}

std::string describe(const HierarchyEvent& event) { return phrase(event).english(); }
std::string describe(const HierarchyCullEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
