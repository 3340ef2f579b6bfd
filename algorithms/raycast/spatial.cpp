// SPDX-License-Identifier: MIT
#include "raycast/spatial.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>

namespace hsr::algo {
namespace {

Box box_of(const std::vector<Vec3>& polygon, double pad) {
    Box b{polygon[0], polygon[0]};
    for (const Vec3& v : polygon) b.lo = glm::min(b.lo, v), b.hi = glm::max(b.hi, v);
    return {b.lo - pad, b.hi + pad};
}

bool overlap(const Box& a, const Box& b) {
    return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
           b.lo.z <= a.hi.z;
}

double extent(const Box& b) { return std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z}); }

// What the build carries down the recursion.
struct Building {
    Octree tree;
    std::vector<Box> boxes;  // each primitive's, padded
    OctreeOptions options;
    std::uint32_t leaves = 0;
    int depth = 0;
};

// BuildOctree(cell): examine it; a leaf if a stopping rule holds, else 8 subcells, each built in turn.
Steps<RayCastEvent, bool> build_cell(Building* b, std::size_t n) {
    const OctreeOptions& o = b->options;
    const Box box = b->tree.nodes[n].box;
    const int depth = b->tree.nodes[n].depth;
    const auto held = std::uint32_t(b->tree.nodes[n].primitives.size());
    const double edge = extent(box);
    b->depth = std::max(b->depth, depth);
    co_yield OctreeCellExamined{std::uint32_t(n), depth, box.lo, box.hi, held};
    const auto leaf = [&](OctreeStop why) {
        ++b->leaves;
        return OctreeLeafMade{std::uint32_t(n), why, held, edge};
    };
    if (held <= o.max_per_leaf) {
        co_yield leaf(OctreeStop::few_primitives);
        co_return true;
    }
    if (depth >= o.max_depth || (o.voxel > 0 && edge / 2 < o.voxel)) {
        co_yield leaf(OctreeStop::voxel_size);
        co_return true;
    }
    if (b->tree.nodes.size() + 8 > o.max_nodes) {
        co_yield leaf(OctreeStop::node_budget);
        co_return true;
    }
    const Vec3 mid = (box.lo + box.hi) * 0.5;
    std::vector<OctreeNode> children(8);
    std::size_t listed = 0;  // primitives over all children, counting each as often as it is listed
    for (int c = 0; c < 8; ++c) {
        OctreeNode& child = children[std::size_t(c)];
        child.depth = depth + 1;
        child.box.lo = {c & 1 ? mid.x : box.lo.x, c & 2 ? mid.y : box.lo.y, c & 4 ? mid.z : box.lo.z};
        child.box.hi = {c & 1 ? box.hi.x : mid.x, c & 2 ? box.hi.y : mid.y, c & 4 ? box.hi.z : mid.z};
        for (std::uint32_t p : b->tree.nodes[n].primitives)
            if (overlap(b->boxes[p], child.box)) child.primitives.push_back(p);
        listed += child.primitives.size();
    }
    // Big primitives listed in most children would multiply, not separate: stay a leaf
    if (listed > 3 * std::size_t(held)) {
        co_yield leaf(OctreeStop::would_multiply);
        co_return true;
    }
    const auto first = std::uint32_t(b->tree.nodes.size());
    b->tree.nodes[n].first_child = std::int32_t(first);
    b->tree.nodes[n].primitives.clear();
    for (auto& child : children) b->tree.nodes.push_back(std::move(child));
    co_yield OctreeCellSplit{std::uint32_t(n), first, std::uint32_t(listed)};
    for (std::uint32_t c = 0; c < 8; ++c) {
        auto sub = build_cell(b, first + c);
        for (const auto& e : sub) co_yield e;
    }
    co_return true;
}

}  // namespace

Box bounds_of(const std::vector<std::vector<Vec3>>& polygons) {
    if (polygons.empty()) return {Vec3(-1), Vec3(1)};
    Box b = box_of(polygons[0], 0);
    for (const auto& p : polygons) {
        const Box q = box_of(p, 0);
        b.lo = glm::min(b.lo, q.lo), b.hi = glm::max(b.hi, q.hi);
    }
    // Never flat along an axis (a scene in one plane still has cells of some thickness)
    const double size = std::max(extent(b), 1e-6), pad = 1e-6 * size;
    for (int a = 0; a < 3; ++a) b.lo[a] -= pad, b.hi[a] += pad;
    return b;
}

std::optional<Interval> ray_box(const Ray& ray, const Box& box, double t0, double t1) {
    Interval t{t0, t1};
    for (int a = 0; a < 3; ++a)
        if (!narrow_to_slab(t, box.lo[a], box.hi[a], ray.origin[a], ray.direction[a])) return std::nullopt;
    return t;
}

Grid build_grid(const std::vector<std::vector<Vec3>>& polygons, int per_axis) {
    Grid g;
    g.box = bounds_of(polygons);
    if (per_axis <= 0) per_axis = std::clamp(int(std::lround(2 * std::cbrt(double(polygons.size())))), 1, 64);
    g.cells = glm::ivec3(per_axis);
    g.size = (g.box.hi - g.box.lo) / Vec3(g.cells);
    g.lists.resize(std::size_t(per_axis) * std::size_t(per_axis) * std::size_t(per_axis));
    const double pad = 1e-9 * extent(g.box);
    for (std::uint32_t p = 0; p < polygons.size(); ++p) {
        const Box b = box_of(polygons[p], pad);
        glm::ivec3 lo, hi;
        for (int a = 0; a < 3; ++a) {
            lo[a] = g.cell_of(b.lo[a], a);
            hi[a] = g.cell_of(b.hi[a], a);
        }
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x)
                    g.lists[std::size_t((z * g.cells.y + y) * g.cells.x + x)].push_back(p);
    }
    return g;
}

Steps<RayCastEvent, Octree> octree_build(std::vector<std::vector<Vec3>> polygons, OctreeOptions options) {
    Building b;
    b.options = options;
    OctreeNode root{bounds_of(polygons), 0, -1, {}};
    const double pad = 1e-9 * extent(root.box);
    for (std::uint32_t p = 0; p < polygons.size(); ++p) {
        b.boxes.push_back(box_of(polygons[p], pad));
        root.primitives.push_back(p);
    }
    b.tree.nodes.push_back(std::move(root));
    auto cells = build_cell(&b, 0);
    for (const auto& e : cells) co_yield e;
    co_yield OctreeBuilt{std::uint32_t(b.tree.nodes.size()), b.leaves, b.depth};
    co_return std::move(b.tree);
}

Octree build_octree(const std::vector<std::vector<Vec3>>& polygons, OctreeOptions options) {
    auto machine = octree_build(polygons, options);
    for (const auto& e : machine) (void)e;
    return std::move(machine).result();
}

}  // namespace hsr::algo
