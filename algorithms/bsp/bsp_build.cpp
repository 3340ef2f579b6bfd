// SPDX-License-Identifier: MIT
// BuildBSP, as the lecture gives it: choose a splitting polygon, classify every other polygon against its plane
// (front, back, coplanar, spanning), split the spanning ones, keep the coplanar ones at the node, recurse.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "bsp/bsp_tree.h"
#include "core/numeric.h"
#include "raster/screen_polygon.h"

#include <glm/common.hpp>

namespace hsr::algo {
Tolerance pair_tolerance(const BspTree& tree, BspPolygonId a, std::span<const Vec3> b) {
    return Tolerance::for_pair(tree.polygons[std::size_t(a)].vertices, b);
}

Tolerance node_tolerance(const BspTree& tree, const BspNode& node, const Vec3& p) {
    return node.polygons.empty() ? tree.tolerance : pair_tolerance(tree, node.polygons.front(), std::span<const Vec3>(&p, 1));
}

namespace {

constexpr std::size_t max_candidates = 32;  // a node scores at most this many splitters (spread over its list)

struct Score {
    std::uint32_t front = 0, back = 0, spanning = 0;
    double value = 0;
};

Score score(const BspTree& t, BspPolygonId candidate, const std::vector<BspPolygonId>& list, const BspOptions& o) {
    Score s;
    const Plane& plane = t.polygons[std::size_t(candidate)].plane;
    for (BspPolygonId p : list) {
        if (p == candidate) continue;
        const auto& vertices = t.polygons[std::size_t(p)].vertices;
        switch (classify(plane, vertices, pair_tolerance(t, candidate, vertices))) {
            case PolygonSide::front: ++s.front; break;
            case PolygonSide::back: ++s.back; break;
            case PolygonSide::spanning: ++s.spanning, ++s.front, ++s.back; break;
            case PolygonSide::coplanar: break;
        }
    }
    const double imbalance = std::fabs(double(s.front) - double(s.back));
    switch (o.splitter) {
        case SplitterRule::first: s.value = 0; break;
        case SplitterRule::balanced: s.value = imbalance; break;  // "roughly equal cardinality"
        case SplitterRule::fewest_splits: s.value = s.spanning; break;
        case SplitterRule::weighted: s.value = o.balance_weight * imbalance + o.split_weight * s.spanning; break;
    }
    return s;
}

BspPolygonId add_part(BspTree& t, BspPolygonId whole, std::vector<Vec3> vertices, const char* side) {
    const BspPolygon& w = t.polygons[std::size_t(whole)];
    BspPolygon part{w.source, w.label + side, std::move(vertices), w.plane};  // a part lies in its whole's plane
    t.polygons.push_back(std::move(part));
    return BspPolygonId(t.polygons.size() - 1);
}

// One call of BuildBSP(list) for a list that is not empty: the node it makes, and the front and back lists it
// would recurse on.
struct Parent {
    BspNodeId node = -1;
    Side side = Side::front;
};
struct ListToBuild {
    std::vector<BspPolygonId> list;
    std::uint32_t depth = 0;
    Parent parent;
};
struct Sides {
    std::vector<BspPolygonId> front, back;
};

Steps<BspEvent, Sides> build_node(BspTree* t, BspNodeId node, ListToBuild in, BspOptions o) {
    std::vector<BspPolygonId>& list = in.list;
    const std::uint32_t depth = in.depth;
    t->nodes[std::size_t(node)].depth = depth;
    t->depth = std::max(t->depth, depth + 1);

    // Choose a splitting polygon
    BspPolygonId splitter = list.front();
    Score best;
    std::uint32_t scored = 1;
    if (o.splitter != SplitterRule::first) {
        best.value = std::numeric_limits<double>::infinity();
        const std::size_t step = std::max<std::size_t>(1, list.size() / max_candidates);
        scored = 0;
        for (std::size_t i = 0; i < list.size() && scored < max_candidates; i += step, ++scored) {
            const Score s = score(*t, list[i], list, o);
            co_yield CandidateScored{node, list[i], s.front, s.back, s.spanning, s.value};
            if (s.value < best.value) best = s, splitter = list[i];
        }
    }
    const Plane plane = t->polygons[std::size_t(splitter)].plane;
    t->nodes[std::size_t(node)].plane = plane;
    co_yield SplitterChosen{node, in.parent.node, in.parent.side, splitter, depth, scored, best.value, plane};

    Sides sides;
    std::vector<BspPolygonId> here{splitter};
    if (depth + 1 >= o.max_depth) {  // bound: keep what is left at this node, in list order
        co_yield BspBoundReached{BspBound::depth, o.max_depth};
        t->bounded = true;
        for (BspPolygonId p : list)
            if (p != splitter) here.push_back(p);
        list.clear();
    }
    // Classify every other polygon against the splitter's plane
    for (BspPolygonId p : list) {
        if (p == splitter) continue;
        if (++t->classifications > *o.max_classifications) {  // bound: this node keeps what is left, unclassified
            co_yield BspBoundReached{BspBound::classifications, *o.max_classifications};
            t->bounded = true;
            for (auto rest = std::find(list.begin(), list.end(), p); rest != list.end(); ++rest)
                if (*rest != splitter) here.push_back(*rest);
            break;
        }
        const Tolerance tol = pair_tolerance(*t, splitter, t->polygons[std::size_t(p)].vertices);
        const PolygonSide side = classify(plane, t->polygons[std::size_t(p)].vertices, tol);
        co_yield PolygonClassified{node, p, side, splitter};
        switch (side) {
            case PolygonSide::front: sides.front.push_back(p); break;
            case PolygonSide::back: sides.back.push_back(p); break;
            case PolygonSide::coplanar: here.push_back(p); break;  // never split against its own plane
            case PolygonSide::spanning: {
                if (t->polygons.size() + 2 > o.max_polygons) {
                    co_yield BspBoundReached{BspBound::polygons, o.max_polygons};
                    t->bounded = true;
                    here.push_back(p);
                    break;
                }
                SplitParts parts = split(plane, t->polygons[std::size_t(p)].vertices, tol);
                auto f = std::make_shared<const std::vector<Vec3>>(parts.front);
                auto b = std::make_shared<const std::vector<Vec3>>(parts.back);
                const BspPolygonId fp = add_part(*t, p, std::move(parts.front), "f");
                const BspPolygonId bp = add_part(*t, p, std::move(parts.back), "b");
                ++t->splits;
                const BspEvent split_event = PolygonSplit{node, p, fp, bp, std::move(f), std::move(b)};
                co_yield split_event;  // by name: see the top of core/steps.h
                sides.front.push_back(fp);
                sides.back.push_back(bp);
                break;
            }
        }
    }
    t->nodes[std::size_t(node)].polygons = here;
    co_yield NodeFinished{node, std::uint32_t(here.size()), std::uint32_t(sides.front.size()), std::uint32_t(sides.back.size()), splitter};
    co_return sides;
}

// BuildBSP(list) from the top: the lecture's recursion (a node, then BuildBSP(front), then BuildBSP(back)) with its
// stack of lists kept by hand. A recursive generator forwards each event through every level above it, so a tree
// 600 deep cost 600 resumes per event; this way every event is passed on once, in the recursion's order.
Steps<BspEvent, BspTree> build_machine(BspTree tree, BspOptions o) {
    co_yield BuildStarted{std::uint32_t(tree.polygons.size()), o.splitter, Tolerance::relative};
    ListToBuild all;
    for (std::size_t i = 0; i < tree.polygons.size(); ++i) all.list.push_back(BspPolygonId(i));
    std::vector<ListToBuild> to_build;  // the top is built next
    to_build.push_back(std::move(all));
    while (!to_build.empty()) {
        ListToBuild next = std::move(to_build.back());
        to_build.pop_back();
        if (next.list.empty()) continue;  // an empty subtree: the parent's link stays −1
        const BspNodeId node = BspNodeId(tree.nodes.size());
        tree.nodes.push_back({});
        const Parent parent = next.parent;
        if (parent.node < 0) tree.root = node;
        else if (parent.side == Side::front) tree.nodes[std::size_t(parent.node)].front = node;
        else tree.nodes[std::size_t(parent.node)].back = node;
        auto one_node = build_node(&tree, node, std::move(next), o);
        for (const auto& e : one_node) co_yield e;
        Sides sides = std::move(one_node).result();
        const std::uint32_t depth = tree.nodes[std::size_t(node)].depth + 1;
        to_build.push_back({std::move(sides.back), depth, {node, Side::back}});    // after the whole front subtree
        to_build.push_back({std::move(sides.front), depth, {node, Side::front}});  // next
    }
    co_yield BuildFinished{std::uint32_t(tree.nodes.size()), tree.depth, std::uint32_t(tree.held()),
                           tree.splits};
    co_return std::move(tree);
}

}  // namespace

std::size_t BspTree::held() const {
    std::size_t n = 0;
    for (const BspNode& node : nodes) n += node.polygons.size();
    return n;
}

std::vector<std::string> BspTree::labels() const {
    std::vector<std::string> out;
    for (const auto& p : polygons) out.push_back(p.label);
    return out;
}

Steps<BspEvent, BspTree> build_bsp(std::vector<BspInput> polygons, BspOptions options) {
    BspTree tree;
    Vec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const BspInput& in : polygons) {
        const std::string name = "polygon " + std::to_string(in.id);
        if (in.vertices.size() < 2) throw InvalidInput(name + " has fewer than 2 vertices");
        for (std::size_t i = 0; i < in.vertices.size(); ++i) {
            const Vec3& v = in.vertices[i];
            require_finite(glm::dvec4(v, 1.0), [&] { return name + " vertex " + std::to_string(i); });
            lo = glm::min(lo, v);
            hi = glm::max(hi, v);
        }
        Plane plane;
        if (!plane_of(in.vertices, plane)) throw InvalidInput(name + " is degenerate (it has no area)");
        require_convex(in.vertices, in.id);  // a split of a concave polygon by a plane can give more than two parts
        tree.polygons.push_back({in.id, std::to_string(in.id), in.vertices, plane});
    }
    if (tree.polygons.size() > options.max_polygons)
        throw InvalidInput(std::to_string(tree.polygons.size()) + " polygons are more than the bound of " +
                           std::to_string(options.max_polygons));
    const Vec3 size = polygons.empty() ? Vec3(1) : hi - lo;
    tree.tolerance = Tolerance::for_extent(std::max({size.x, size.y, size.z}));
    if (!options.max_classifications)
        options.max_classifications = std::uint32_t(std::clamp<std::uint64_t>(256 * std::uint64_t(tree.polygons.size()), 1u << 24, 1u << 28));
    return build_machine(std::move(tree), options);
}

}  // namespace hsr::algo
