// SPDX-License-Identifier: MIT
#include "bsp/bsp_events.h"

#include <cstdio>

#include "core/overloaded.h"

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

std::string_view to_string(SplitterRule r) {
    switch (r) {
        case SplitterRule::first: return "first polygon";
        case SplitterRule::balanced: return "most balanced";
        case SplitterRule::fewest_splits: return "fewest splits";
        case SplitterRule::weighted: return "weighted";
    }
    return "?";
}

std::string_view to_string(BspBound b) {
    switch (b) {
        case BspBound::depth: return "tree depth";
        case BspBound::polygons: return "polygons";
        case BspBound::classifications: return "classifications";
    }
    return "?";
}

std::string describe(const BspEvent& event, const PolygonNamer& name) {
    const auto node = [](BspNodeId n) { return "node " + std::to_string(n); };
    return std::visit(
        overloaded{
            [&](const BuildStarted& e) {
                return "build a BSP tree of " + std::to_string(e.polygons) + " polygons, splitter rule: " +
                       std::string(to_string(e.rule)) + ", ε = " + num(e.tolerance) + " × the size of the polygons compared";
            },
            [&](const CandidateScored& e) {
                return node(e.node) + ": splitter " + name(e.candidate) + " would leave " + std::to_string(e.front) +
                       " in front, " + std::to_string(e.back) + " behind, split " + std::to_string(e.spanning) +
                       ": score " + num(e.score);
            },
            [&](const SplitterChosen& e) {
                std::string out = node(e.node) + " (depth " + std::to_string(e.depth) + "): " + name(e.splitter) +
                                  " splits";
                if (e.candidates > 1)
                    out += ", the best of " + std::to_string(e.candidates) + " candidates (score " + num(e.score) + ")";
                return out;
            },
            [&](const PolygonClassified& e) {
                return name(e.polygon) + " is " + std::string(to_string(e.side)) + " of " + node(e.node) + "'s plane";
            },
            [&](const PolygonSplit& e) {
                return name(e.polygon) + " spans the plane: split into " + name(e.front_part) + " (front, " +
                       std::to_string(e.front ? e.front->size() : 0) + " vertices) and " + name(e.back_part) +
                       " (back, " + std::to_string(e.back ? e.back->size() : 0) + " vertices)";
            },
            [&](const NodeFinished& e) {
                return node(e.node) + " keeps " + std::to_string(e.coplanar) + " polygon(s); " +
                       std::to_string(e.front) + " go to the front subtree, " + std::to_string(e.back) + " to the back";
            },
            [&](const BuildFinished& e) {
                return "built: " + std::to_string(e.nodes) + " nodes, depth " + std::to_string(e.depth) + ", " +
                       std::to_string(e.polygons) + " polygons in its nodes after " + std::to_string(e.splits) + " splits";
            },
            [&](const EyeClassified& e) {
                return "the eye is " + std::string(to_string(e.side)) + " of " + node(e.node) + "'s plane (distance " +
                       num(e.distance) + "): " +
                       ((e.side == Side::back) == (e.order == Order::back_to_front) ? "front subtree first"
                                                                                     : "back subtree first");
            },
            [&](const PolygonDrawn& e) {
                return "draw " + name(e.polygon) + " (number " + std::to_string(e.order) + ")";
            },
            [&](const TraversalFinished& e) { return std::to_string(e.drawn) + " polygons drawn"; },
            [&](const BspBoundReached& e) {
                return "stopped: the bound of " + std::to_string(e.limit) + " " + std::string(to_string(e.bound)) +
                       " was reached; what is left stays at this node";
            },
        },
        event);
}

}  // namespace hsr::algo
