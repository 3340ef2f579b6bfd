// SPDX-License-Identifier: MIT
#include "bsp/bsp_events.h"

#include <cstdio>

#include "core/overloaded.h"
#include "core/phrase.h"

namespace hsr::algo {
namespace {

std::string num(double v) { return format_number(v); }

}  // namespace

bool same_vertices(const VertexList& a, const VertexList& b) {
    if (a == b) return true;
    return a && b && *a == *b;
}

std::optional<SplitterRule> parse_splitter_rule(std::string_view name) {
    if (name == "first") return SplitterRule::first;
    if (name == "balanced") return SplitterRule::balanced;
    if (name == "fewest-splits") return SplitterRule::fewest_splits;
    if (name == "weighted") return SplitterRule::weighted;
    return std::nullopt;
}

namespace {
// What the BSP machines say, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying first{"bsp.first", "first polygon"};
constexpr Saying balanced{"bsp.balanced", "most balanced"};
constexpr Saying fewest_splits{"bsp.fewest_splits", "fewest splits"};
constexpr Saying weighted{"bsp.weighted", "weighted"};
constexpr Saying depth{"bsp.depth", "tree depth"};
constexpr Saying polygons{"bsp.polygons", "polygons"};
constexpr Saying classifications{"bsp.classifications", "classifications"};
// the sides' names, as a lesson's question offers them for a choice
constexpr Saying side_front{"bsp.side_front", "front"};
constexpr Saying side_back{"bsp.side_back", "back"};
constexpr Saying side_coplanar{"bsp.side_coplanar", "coplanar"};
constexpr Saying side_spanning{"bsp.side_spanning", "spanning"};
constexpr Saying front_first{"bsp.front_first", "front subtree first"};
constexpr Saying back_first{"bsp.back_first", "back subtree first"};
constexpr Saying build_started{"bsp.build_started",
                               "build a BSP tree of {polygons} polygons, splitter rule: {rule}, ε = {tolerance} × the size of "
                               "the smaller polygon compared"};
constexpr Saying candidate{"bsp.candidate",
                           "splitter {candidate} would leave {front} in front, {back} behind, split {spanning}: "
                           "score {score}"};
constexpr Saying chosen{"bsp.chosen", "a new node at depth {depth}: polygon {splitter} is its splitter"};
constexpr Saying chosen_best{"bsp.chosen_best",
                             "a new node at depth {depth}: polygon {splitter} is its splitter, the best of {candidates} candidates (score {score})"};
constexpr Saying in_front{"bsp.in_front", "{polygon} is in front of the plane of {splitter}"};
constexpr Saying behind{"bsp.behind", "{polygon} is behind the plane of {splitter}"};
constexpr Saying coplanar{"bsp.coplanar", "{polygon} is coplanar with {splitter}"};
constexpr Saying spanning{"bsp.spanning", "{polygon} spans the plane of {splitter}"};
constexpr Saying split{"bsp.split",
                       "{polygon} spans the plane: split into {front_part} (front, {front} {front?vertex|vertices}) and "
                       "{back_part} (back, {back} {back?vertex|vertices})"};
constexpr Saying node_finished{"bsp.node_finished",
                               "the node of {splitter} keeps {coplanar} {coplanar?polygon|polygons}; {front} go to the front subtree, {back} to the back"};
constexpr Saying built{"bsp.built",
                       "built: {nodes} nodes, depth {depth}, {polygons} polygons in its nodes after {splits} splits"};
constexpr Saying eye_front{"bsp.eye_front", "the eye is in front of the plane of {splitter} (distance {distance}): {first}"};
constexpr Saying eye_back{"bsp.eye_back", "the eye is behind the plane of {splitter} (distance {distance}): {first}"};
constexpr Saying eye_on{"bsp.eye_on", "the eye is on the plane of {splitter} (distance {distance}): {first}"};
constexpr Saying drawn{"bsp.drawn", "draw {polygon} (number {order})"};
constexpr Saying traversal_finished{"bsp.traversal_finished", "{drawn} polygons drawn"};
constexpr Saying bound_reached{"bsp.bound_reached", "stopped: the bound of {limit} {bound} was reached; what is left stays at this node"};
constexpr Saying all[] = {first, balanced, fewest_splits, weighted, depth, polygons, classifications, side_front, side_back,
                          side_coplanar, side_spanning, front_first, back_first,
                          build_started, candidate, chosen, chosen_best, in_front, behind, coplanar, spanning, split,
                          node_finished, built, eye_front, eye_back, eye_on, drawn, traversal_finished, bound_reached};
}  // namespace say
}  // namespace

const Saying& term(SplitterRule r) {
    switch (r) {
        case SplitterRule::first: return say::first;
        case SplitterRule::balanced: return say::balanced;
        case SplitterRule::fewest_splits: return say::fewest_splits;
        case SplitterRule::weighted: return say::weighted;
    }
    return say::first;
}

const Saying& term(BspBound b) {
    switch (b) {
        case BspBound::depth: return say::depth;
        case BspBound::polygons: return say::polygons;
        case BspBound::classifications: return say::classifications;
    }
    return say::depth;
}

std::string_view to_string(SplitterRule r) { return term(r).english; }
std::string_view to_string(BspBound b) { return term(b).english; }

std::span<const Saying> bsp_sayings() { return say::all; }

Phrase phrase(const BspEvent& event, const PolygonNamer& name) {
    const auto n = [](auto v) { return std::to_string(v); };
    return std::visit(
        overloaded{
            [&](const BuildStarted& e) {
                return Phrase(say::build_started, {{"polygons", n(e.polygons)}, {"tolerance", num(e.tolerance)}}, Terms{{"rule", &term(e.rule)}});
            },
            [&](const CandidateScored& e) {
                return Phrase(say::candidate, {{"candidate", name(e.candidate)},
                                               {"front", n(e.front)},
                                               {"back", n(e.back)},
                                               {"spanning", n(e.spanning)},
                                               {"score", num(e.score)}});
            },
            [&](const SplitterChosen& e) {
                return Phrase(e.candidates > 1 ? say::chosen_best : say::chosen,
                              {{"depth", n(e.depth)}, {"splitter", name(e.splitter)},
                               {"candidates", n(e.candidates)}, {"score", num(e.score)}});
            },
            [&](const PolygonClassified& e) {
                const Saying& saying = e.side == PolygonSide::front  ? say::in_front
                                       : e.side == PolygonSide::back ? say::behind
                                       : e.side == PolygonSide::coplanar ? say::coplanar
                                                                         : say::spanning;
                return Phrase(saying, {{"polygon", name(e.polygon)}, {"splitter", name(e.splitter)}});
            },
            [&](const PolygonSplit& e) {
                return Phrase(say::split, {{"polygon", name(e.polygon)},
                                           {"front_part", name(e.front_part)},
                                           {"front", n(e.front ? e.front->size() : 0)},
                                           {"back_part", name(e.back_part)},
                                           {"back", n(e.back ? e.back->size() : 0)}});
            },
            [&](const NodeFinished& e) {
                return Phrase(say::node_finished, {{"splitter", name(e.splitter)}, {"coplanar", n(e.coplanar)}, {"front", n(e.front)}, {"back", n(e.back)}});
            },
            [&](const BuildFinished& e) {
                return Phrase(say::built, {{"nodes", n(e.nodes)}, {"depth", n(e.depth)}, {"polygons", n(e.polygons)}, {"splits", n(e.splits)}});
            },
            [&](const EyeClassified& e) {
                const bool front_first = (e.side == Side::back) == (e.order == Order::back_to_front);
                return Phrase(e.side == Side::front ? say::eye_front : e.side == Side::back ? say::eye_back : say::eye_on,
                              {{"splitter", name(e.splitter)}, {"distance", num(e.distance)}},
                              Terms{{"first", front_first ? &say::front_first : &say::back_first}});
            },
            [&](const PolygonDrawn& e) { return Phrase(say::drawn, {{"polygon", name(e.polygon)}, {"order", n(e.order)}}); },
            [&](const TraversalFinished& e) { return Phrase(say::traversal_finished, {{"drawn", n(e.drawn)}}); },
            [&](const BspBoundReached& e) { return Phrase(say::bound_reached, {{"limit", n(e.limit)}}, Terms{{"bound", &term(e.bound)}}); },
        },
        event);
}

std::string describe(const BspEvent& event, const PolygonNamer& name) { return phrase(event, name).english(); }

}  // namespace hsr::algo
