// SPDX-License-Identifier: MIT
#include "culling/culling_events.h"

#include "core/events.h"
#include "core/overloaded.h"
#include "core/phrase.h"

namespace hsr::algo {
namespace {

std::string n(std::uint64_t v) { return std::to_string(v); }

}  // namespace

namespace {
// What the hierarchy's build and cull say, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying outside{"culling.outside", "outside"};
constexpr Saying inside{"culling.inside", "inside"};
constexpr Saying partial{"culling.partial", "partly inside"};
constexpr Saying too_small{"culling.too_small", "too small"};
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
constexpr Saying node_too_small{"culling.node_too_small",
                                "Node {node} ({primitives} primitives): {outcome} ({pixels} pixels) after {tests} {tests?plane test|plane tests}."};
constexpr Saying done{"culling.done",
                      "Done: {nodes} nodes, {tests} plane tests; {kept} primitives kept, {outside} outside, {too_small} too small."};
constexpr Saying all[] = {outside, inside, partial, too_small, split, few_primitives, cell_size, depth_bound, node_built, built,
                          node, node_outside, node_too_small, done};
}  // namespace say
}  // namespace

const Saying& term(NodeOutcome o) {
    switch (o) {
        case NodeOutcome::outside: return say::outside;
        case NodeOutcome::inside: return say::inside;
        case NodeOutcome::partial: return say::partial;
        case NodeOutcome::too_small: return say::too_small;
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
                const Saying& saying = e.outcome == NodeOutcome::outside     ? say::node_outside
                                       : e.outcome == NodeOutcome::too_small ? say::node_too_small
                                                                             : say::node;
                return Phrase(saying,
                              {{"node", n(e.node)}, {"primitives", n(e.primitives)}, {"plane", n(std::uint64_t(e.plane))},
                               {"pixels", format_number(e.pixels)}, {"tests", n(e.planes_tested)}},
                              Terms{{"outcome", &term(e.outcome)}});
            },
            [](const HierarchyCullFinished& e) {
                return Phrase(say::done, {{"nodes", n(e.nodes_tested)}, {"tests", n(e.plane_tests)}, {"kept", n(e.kept)},
                                          {"outside", n(e.outside)}, {"too_small", n(e.too_small)}});
            },
        },
        event);
}

std::string describe(const HierarchyEvent& event) { return phrase(event).english(); }
std::string describe(const HierarchyCullEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
