// SPDX-License-Identifier: MIT
// The facts of BSP build (the lecture's BuildBSP) and traversal (DisplayBSP). Polygons are named by their index in
// the tree's polygon table (inputs first, then split parts in the order they are made); a split carries the two
// parts' vertices as immutable shared lists, so events stay small and a view can draw a part the moment it appears.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <span>
#include <variant>
#include <vector>

#include "core/events.h"
#include "core/phrase.h"
#include "core/plane.h"

namespace hsr::algo {

using BspPolygonId = std::int32_t;  // index into BspTree::polygons
using BspNodeId = std::int32_t;     // index into BspTree::nodes; −1 is an empty subtree
using VertexList = std::shared_ptr<const std::vector<Vec3>>;

enum class SplitterRule : std::uint8_t { first, balanced, fewest_splits, weighted };
enum class BspBound : std::uint8_t { depth, polygons, classifications };
enum class Order : std::uint8_t { back_to_front, front_to_back };

bool same_vertices(const VertexList& a, const VertexList& b);  // by content

// ── build ───────────────────────────────────────────────────────────────────────────────────────────────────
struct BuildStarted {
    static constexpr std::string_view kind = "BuildStarted";
    std::uint32_t polygons;
    SplitterRule rule;
    double tolerance;  // the classification ε, relative: a share of the size of the smaller polygon compared
    bool operator==(const BuildStarted&) const = default;
};
// One candidate splitter scored against the other polygons of the node (a micro-step).
struct CandidateScored {
    static constexpr std::string_view kind = "CandidateScored";
    BspNodeId node;
    BspPolygonId candidate;
    std::uint32_t front, back, spanning;
    double score;  // lower is better
    bool operator==(const CandidateScored&) const = default;
};
struct SplitterChosen {
    static constexpr std::string_view kind = "SplitterChosen";
    BspNodeId node;
    BspNodeId parent;  // −1 for the root
    Side side;         // which side of the parent this node is on (front or back)
    BspPolygonId splitter;
    std::uint32_t depth;
    std::uint32_t candidates;  // how many were scored (1 for the first-polygon rule)
    double score;
    Plane plane;
    bool operator==(const SplitterChosen&) const = default;
};
struct PolygonClassified {
    static constexpr std::string_view kind = "PolygonClassified";
    BspNodeId node;
    BspPolygonId polygon;
    PolygonSide side;
    BspPolygonId splitter;  // the node's splitter: its plane is the one tested, and the picture names nodes by it
    bool operator==(const PolygonClassified&) const = default;
};
struct PolygonSplit {
    static constexpr std::string_view kind = "PolygonSplit";
    BspNodeId node;
    BspPolygonId polygon;
    BspPolygonId front_part, back_part;
    VertexList front, back;
    bool operator==(const PolygonSplit& o) const {
        return node == o.node && polygon == o.polygon && front_part == o.front_part && back_part == o.back_part &&
               same_vertices(front, o.front) && same_vertices(back, o.back);
    }
};
struct NodeFinished {
    static constexpr std::string_view kind = "NodeFinished";
    BspNodeId node;
    std::uint32_t coplanar, front, back;  // polygons kept at the node, sent to each side
    BspPolygonId splitter;
    bool operator==(const NodeFinished&) const = default;
};
struct BuildFinished {
    static constexpr std::string_view kind = "BuildFinished";
    std::uint32_t nodes, depth, polygons, splits;  // polygons: held by the nodes (drawn by a traversal)
    bool operator==(const BuildFinished&) const = default;
};

// ── traversal ───────────────────────────────────────────────────────────────────────────────────────────────
struct EyeClassified {
    static constexpr std::string_view kind = "EyeClassified";
    BspNodeId node;
    Side side;
    Order order;
    double distance;  // signed distance of the eye from the node's plane
    BspPolygonId splitter;  // the node's first polygon, whose plane it is
    bool operator==(const EyeClassified&) const = default;
};
struct PolygonDrawn {
    static constexpr std::string_view kind = "PolygonDrawn";
    BspNodeId node;
    BspPolygonId polygon;
    std::uint32_t order;  // 1 for the first polygon painted
    Side eye_side;        // the eye's side of the node's plane
    bool leaf;            // the node has no children
    bool operator==(const PolygonDrawn&) const = default;
};
struct TraversalFinished {
    static constexpr std::string_view kind = "TraversalFinished";
    std::uint32_t drawn;
    bool operator==(const TraversalFinished&) const = default;
};

struct BspBoundReached {
    static constexpr std::string_view kind = "BspBoundReached";
    BspBound bound;
    std::uint32_t limit;
    bool operator==(const BspBoundReached&) const = default;
};

using BspEvent = std::variant<BuildStarted, CandidateScored, SplitterChosen, PolygonClassified, PolygonSplit,
                              NodeFinished, BuildFinished, EyeClassified, PolygonDrawn, TraversalFinished,
                              BspBoundReached>;

// Names a polygon as the view does ("3", "3f", "3fb"); describe uses it for every polygon it mentions.
using PolygonNamer = std::function<std::string(BspPolygonId)>;
// What an event says, as a template with named values (core/phrase.h), and in English.
Phrase phrase(const BspEvent& e, const PolygonNamer& name);
std::string describe(const BspEvent& e, const PolygonNamer& name);
const Saying& term(SplitterRule r);  // words to translate
const Saying& term(BspBound b);
std::span<const Saying> bsp_sayings();  // every template the BSP machines say
std::string_view to_string(SplitterRule r);  // as sentences name it: "most balanced"
// As files and the command line name a rule: "first", "balanced", "fewest-splits", "weighted"; nullopt otherwise.
std::optional<SplitterRule> parse_splitter_rule(std::string_view name);
inline constexpr std::string_view splitter_rule_names = "first, balanced, fewest-splits or weighted";
std::string_view to_string(BspBound b);

}  // namespace hsr::algo
