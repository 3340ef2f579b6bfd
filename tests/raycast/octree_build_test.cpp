// SPDX-License-Identifier: MIT
// BuildOctree as a machine: every cell examined, then split or made a leaf by the notes' two stopping rules (few
// enough primitives; the voxel size), checked cell by cell against the rules and against a brute-force listing of
// the primitives each leaf must hold; the leaves tile the root; the rays through it still see what brute force sees.
#include <algorithm>
#include <cmath>
#include <map>

#include "catch.h"
#include "raycast/ray_cast.h"
#include "raycast/spatial.h"
#include "scene/random_scene.h"
#include "scene/polygons_of.h"

using namespace hsr::algo;
using hsr::test::polygons_of;

namespace {

struct Told {
    std::vector<RayCastEvent> events;
    Octree tree;
};
Told build(const std::vector<std::vector<Vec3>>& polygons, OctreeOptions o) {
    Told t;
    auto machine = octree_build(polygons, o);
    for (const auto& e : machine) t.events.push_back(e);
    t.tree = std::move(machine).result();
    return t;
}

double volume(const Box& b) { return (b.hi.x - b.lo.x) * (b.hi.y - b.lo.y) * (b.hi.z - b.lo.z); }
double longest(const Box& b) { return std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z}); }

// The primitives whose box, padded as the octree pads it, meets the cell: computed here on its own.
std::vector<std::uint32_t> meeting(const std::vector<std::vector<Vec3>>& polygons, const Box& cell, double pad) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t p = 0; p < polygons.size(); ++p) {
        Vec3 lo = polygons[p][0], hi = polygons[p][0];
        for (const Vec3& v : polygons[p]) lo = glm::min(lo, v), hi = glm::max(hi, v);
        lo -= pad, hi += pad;
        bool meets = true;
        for (int a = 0; a < 3; ++a) meets = meets && lo[a] <= cell.hi[a] && cell.lo[a] <= hi[a];
        if (meets) out.push_back(p);
    }
    return out;
}

// Checks one build against its options; returns the leaves' stopping reasons, counted.
std::map<OctreeStop, int> check_build(const std::vector<std::vector<Vec3>>& polygons, OctreeOptions o) {
    const Told t = build(polygons, o);
    const Octree& tree = t.tree;
    REQUIRE(!tree.nodes.empty());
    const Box root = tree.nodes[0].box;
    const double pad = 1e-9 * longest(root);
    std::map<std::uint32_t, std::uint32_t> examined;  // node → primitives, as told
    std::map<OctreeStop, int> reasons;
    double leaf_volume = 0;
    for (const auto& e : t.events) {
        if (const auto* x = std::get_if<OctreeCellExamined>(&e)) {
            REQUIRE(x->node < tree.nodes.size());
            examined[x->node] = x->primitives;
        } else if (const auto* l = std::get_if<OctreeLeafMade>(&e)) {
            REQUIRE(examined.count(l->node) == 1);  // examined before it is decided
            const OctreeNode& node = tree.nodes[l->node];
            CHECK(node.first_child == -1);
            CHECK(node.primitives == meeting(polygons, node.box, pad));
            ++reasons[l->reason];
            leaf_volume += volume(node.box);
            const bool voxel = node.depth >= o.max_depth || (o.voxel > 0 && longest(node.box) / 2 < o.voxel);
            switch (l->reason) {
                case OctreeStop::few_primitives: CHECK(node.primitives.size() <= o.max_per_leaf); break;
                case OctreeStop::voxel_size:
                    CHECK(node.primitives.size() > o.max_per_leaf);
                    CHECK(voxel);
                    break;
                case OctreeStop::node_budget: CHECK(tree.nodes.size() + 8 > o.max_nodes); break;
                case OctreeStop::would_multiply: CHECK(node.primitives.size() > o.max_per_leaf); break;
            }
        } else if (const auto* s = std::get_if<OctreeCellSplit>(&e)) {
            REQUIRE(examined.count(s->node) == 1);
            const OctreeNode& node = tree.nodes[s->node];
            CHECK(node.first_child == std::int32_t(s->first_child));
            CHECK(examined[s->node] > o.max_per_leaf);  // split only what holds too many …
            CHECK(node.depth < o.max_depth);             // … and is bigger than a voxel
            CHECK(!(o.voxel > 0 && longest(node.box) / 2 < o.voxel));
        } else if (const auto* b = std::get_if<OctreeBuilt>(&e)) {
            CHECK(b->nodes == tree.nodes.size());
            CHECK(std::size_t(b->leaves) == std::size_t(std::count_if(tree.nodes.begin(), tree.nodes.end(), [](const OctreeNode& n) { return n.first_child < 0; })));
        }
    }
    CHECK(examined.size() == tree.nodes.size());  // every cell examined once
    CHECK(leaf_volume == Approx(volume(root)).epsilon(1e-9));  // the leaves tile the root
    return reasons;
}

}  // namespace

TEST_CASE("BuildOctree's cells obey the stopping rules and list what meets them", "[raycast][octree]") {
    for (std::uint32_t seed = 1; seed <= 6; ++seed) {
        const auto polygons = polygons_of(random_triangles({.count = 40 * seed, .seed = seed, .size = 0.3 + 0.2 * seed}));
        for (const OctreeOptions o : {OctreeOptions{}, OctreeOptions{.max_per_leaf = 2, .voxel = 0.8},
                                      OctreeOptions{.max_per_leaf = 1, .max_depth = 3}}) {
            INFO("seed " << seed << ", limit " << o.max_per_leaf << ", voxel " << o.voxel << ", depth " << o.max_depth);
            check_build(polygons, o);
            // the machine's tree is the one build_octree returns
            const Octree direct = build_octree(polygons, o);
            const Told t = build(polygons, o);
            REQUIRE(direct.nodes.size() == t.tree.nodes.size());
            for (std::size_t i = 0; i < direct.nodes.size(); ++i) CHECK(direct.nodes[i].primitives == t.tree.nodes[i].primitives);
        }
    }
}

TEST_CASE("A dense cluster stops at the voxel size, sparse space at few primitives", "[raycast][octree][extremes]") {
    // 60 tiny triangles round one point, and one big triangle far away: only the voxel stops the cluster's cells
    std::vector<std::vector<Vec3>> polygons;
    for (int i = 0; i < 60; ++i) {
        const double a = 0.001 * i;
        polygons.push_back({{a, 0, 0}, {a + 1e-4, 0, 0}, {a, 1e-4, 1e-4}});
    }
    polygons.push_back({{9, 9, 9}, {10, 9, 9}, {9, 10, 10}});
    const OctreeOptions o{.max_per_leaf = 4, .voxel = 0.3};
    const auto reasons = check_build(polygons, o);
    CHECK(reasons.at(OctreeStop::voxel_size) >= 1);
    CHECK(reasons.at(OctreeStop::few_primitives) >= 7);
    const Octree tree = build_octree(polygons, o);
    int depth = 0;
    for (const auto& n : tree.nodes) depth = std::max(depth, n.depth);
    // the root's edge is about 10: halving stops once a subcell's edge would fall below 0.3
    CHECK(depth == int(std::ceil(std::log2(longest(tree.nodes[0].box) / 0.3))) - 1);
}

TEST_CASE("The ray cast tells the build before its first ray, and sees what brute force sees", "[raycast][octree]") {
    const Scene s = random_triangles({.count = 150, .seed = 9, .size = 1.0});
    const Viewport vp{32, 24};
    const RayCastResult brute = ray_cast(s, {.viewport = vp, .acceleration = Acceleration::none, .detail = RayDetail::ray}).run_to_end();
    for (const OctreeOptions o : {OctreeOptions{.max_per_leaf = 2, .voxel = 0.5}, OctreeOptions{.max_per_leaf = 30}}) {
        auto machine = ray_cast(s, {.viewport = vp, .acceleration = Acceleration::octree, .detail = RayDetail::cell, .octree = o});
        bool built = false, ray_before_built = false;
        for (const auto& e : machine) {
            built = built || std::holds_alternative<OctreeBuilt>(e);
            ray_before_built = ray_before_built || (!built && std::holds_alternative<RayStarted>(e));
        }
        CHECK(built);
        CHECK(!ray_before_built);
        CHECK(machine.result().polygon == brute.polygon);
        CHECK(machine.result().t == brute.t);
    }
}
