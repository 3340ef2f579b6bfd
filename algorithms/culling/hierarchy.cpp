// SPDX-License-Identifier: MIT
#include "culling/hierarchy.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "culling/view_frustum.h"

namespace hsr::algo {
namespace {

struct Pending {
    std::uint32_t node;
    std::vector<std::uint32_t> primitives;
};

// BVH: the node's box is its primitives'; split at the median centroid along the longest axis of the centroids.
std::vector<std::vector<std::uint32_t>> bvh_split(const Hierarchy& h, std::vector<std::uint32_t>& prims) {
    Aabb centres;
    for (std::uint32_t p : prims) centres.add(h.boxes[p].centre());
    const Vec3 size = centres.size();
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
    if (size[axis] <= 0) return {};  // every centre at one point: nothing to split by
    const auto mid = prims.begin() + std::ptrdiff_t(prims.size() / 2);
    std::nth_element(prims.begin(), mid, prims.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return h.boxes[a].centre()[axis] < h.boxes[b].centre()[axis]; });
    return {{prims.begin(), mid}, {mid, prims.end()}};
}

// Octree: each primitive goes to the octant that holds its box whole; those that straddle the centre stay.
std::vector<std::pair<Aabb, std::vector<std::uint32_t>>> octree_split(const Hierarchy& h, const Aabb& cell,
                                                                     std::vector<std::uint32_t>& prims) {
    const Vec3 c = cell.centre();
    std::vector<std::uint32_t> octant_of(8);
    std::vector<std::pair<Aabb, std::vector<std::uint32_t>>> children(8);
    for (int k = 0; k < 8; ++k)
        for (int a = 0; a < 3; ++a) {
            const bool high = (k >> a) & 1;
            children[std::size_t(k)].first.lo[a] = high ? c[a] : cell.lo[a];
            children[std::size_t(k)].first.hi[a] = high ? cell.hi[a] : c[a];
        }
    std::vector<std::uint32_t> stay;
    for (std::uint32_t p : prims) {
        int k = 0;
        bool fits = true;
        for (int a = 0; a < 3 && fits; ++a) {
            if (h.boxes[p].hi[a] <= c[a]) continue;
            if (h.boxes[p].lo[a] >= c[a]) k |= 1 << a;
            else fits = false;
        }
        (fits ? children[std::size_t(k)].second : stay).push_back(p);
    }
    prims = std::move(stay);
    std::erase_if(children, [](const auto& c2) { return c2.second.empty(); });
    return children;
}

}  // namespace

std::vector<Aabb> polygon_boxes(const Scene& s) {
    std::vector<Aabb> out;
    for (const auto& p : s.polygons) {
        Aabb b;
        for (const auto& v : p.vertices) b.add(Vec3(v));
        out.push_back(b);
    }
    return out;
}

bool box_passes(const Aabb& box, const std::vector<Plane>& f, std::uint8_t mask, std::uint32_t* tests) {
    for (std::size_t k = 0; k < f.size() && k < 8; ++k) {
        if (!(mask & (1 << k))) continue;
        if (tests) ++*tests;
        if (box_side(box, f[k]) < 0) return false;
    }
    return true;
}

int box_side(const Aabb& b, const Plane& p) {
    const Vec3 pv(p.n.x >= 0 ? b.hi.x : b.lo.x, p.n.y >= 0 ? b.hi.y : b.lo.y, p.n.z >= 0 ? b.hi.z : b.lo.z);
    const Vec3 nv(p.n.x >= 0 ? b.lo.x : b.hi.x, p.n.y >= 0 ? b.lo.y : b.hi.y, p.n.z >= 0 ? b.lo.z : b.hi.z);
    if (p.distance(pv) < 0) return -1;
    if (p.distance(nv) >= 0) return 1;
    return 0;
}

double projected_pixels(const Aabb& b, const Camera& c, int viewport_height) {
    const double r = glm::length(b.size()) / 2;
    if (c.projection == Projection::orthographic) return 2 * r * viewport_height / (c.box[3] - c.box[2]);
    const double z = glm::dot(b.centre() - c.eye, glm::normalize(c.target - c.eye));
    if (z - r <= 0) return std::numeric_limits<double>::infinity();
    return 2 * r / z * viewport_height / (2 * std::tan(c.fov_y * M_PI / 360));
}

Steps<HierarchyEvent, Hierarchy> build_hierarchy(std::vector<Aabb> boxes, HierarchyOptions o) {
    Hierarchy h{o.kind, {}, std::move(boxes), 0};
    if (h.boxes.empty()) {
        co_yield HierarchyBuilt{0, 0, 0};
        co_return h;
    }
    Aabb all;
    for (const Aabb& b : h.boxes) all.add(b);
    if (o.kind == HierarchyKind::octree) {  // the root cell: a cube round everything
        const double half = std::max({all.size().x, all.size().y, all.size().z}) / 2 * (1 + 1e-9) + 1e-12;
        all = {all.centre() - Vec3(half), all.centre() + Vec3(half)};
    }
    const double min_cell = o.min_cell > 0 ? o.min_cell : all.size().x / 1024;
    std::vector<std::uint32_t> everything(h.boxes.size());
    for (std::uint32_t i = 0; i < everything.size(); ++i) everything[i] = i;
    h.nodes.push_back({all, -1, {}, {}, 0, std::uint32_t(everything.size())});
    std::vector<Pending> todo{{0, std::move(everything)}};
    std::uint32_t leaves = 0;
    while (!todo.empty()) {
        Pending p = std::move(todo.back());
        todo.pop_back();
        HierarchyNode& node = h.nodes[p.node];
        const std::uint32_t count = std::uint32_t(p.primitives.size()), depth = node.depth;
        const Aabb cell = node.box;
        const std::int32_t parent = node.parent;
        h.depth = std::max(h.depth, depth + 1);
        // A leaf: few enough primitives, a cell small enough, or the depth bound
        LeafReason leaf = count <= o.max_primitives                                        ? LeafReason::few_primitives
                          : o.kind == HierarchyKind::octree && cell.size().x <= min_cell ? LeafReason::cell_size
                          : depth >= o.max_depth                                          ? LeafReason::depth_bound
                                                                                          : LeafReason::not_a_leaf;
        std::vector<std::pair<Aabb, std::vector<std::uint32_t>>> children;
        if (leaf == LeafReason::not_a_leaf) {
            if (o.kind == HierarchyKind::bvh) {
                for (auto& part : bvh_split(h, p.primitives)) {
                    Aabb b;
                    for (std::uint32_t q : part) b.add(h.boxes[q]);
                    children.push_back({b, std::move(part)});
                }
                if (!children.empty()) p.primitives.clear();
            } else {
                children = octree_split(h, cell, p.primitives);
            }
            if (children.empty()) leaf = LeafReason::few_primitives;  // nothing could be split off
        }
        h.nodes[p.node].primitives = std::move(p.primitives);
        leaves += children.empty();
        co_yield HierarchyNodeBuilt{p.node, parent, depth, count, cell, leaf};
        for (auto it = children.rbegin(); it != children.rend(); ++it) {  // the first child is built first
            const auto child = std::uint32_t(h.nodes.size());
            h.nodes.push_back({it->first, std::int32_t(p.node), {}, {}, depth + 1, std::uint32_t(it->second.size())});
            h.nodes[p.node].children.insert(h.nodes[p.node].children.begin(), child);
            todo.push_back({child, std::move(it->second)});
        }
    }
    co_yield HierarchyBuilt{std::uint32_t(h.nodes.size()), leaves, h.depth};
    co_return h;
}

Steps<HierarchyCullEvent, HierarchyCull> cull_hierarchy(const Hierarchy* h, Camera camera, HierarchyCullOptions o) {
    HierarchyCull out;
    out.kept.assign(h->boxes.size(), 0);
    const std::vector<Plane> frustum = view_frustum(camera);
    const auto each_below = [&](std::uint32_t top, auto&& visit) {
        std::vector<std::uint32_t> stack{top};
        while (!stack.empty()) {
            const std::uint32_t n = stack.back();
            stack.pop_back();
            for (std::uint32_t p : h->nodes[n].primitives) visit(p);
            for (std::uint32_t c : h->nodes[n].children) stack.push_back(c);
        }
    };
    const auto candidate = [&](std::uint32_t p) { return o.candidates.empty() || o.candidates[p] != 0; };
    // per node: the primitives in its subtree that reached this stage (a child's index is above its parent's)
    std::vector<std::uint32_t> below(h->nodes.size(), 0);
    for (std::size_t n = h->nodes.size(); n-- > 0;) {
        for (std::uint32_t p : h->nodes[n].primitives) below[n] += candidate(p);
        if (const std::int32_t parent = h->nodes[n].parent; parent >= 0) below[std::size_t(parent)] += below[n];
    }
    const auto candidates_below = [&](std::uint32_t top) { return below[top]; };
    std::vector<std::pair<std::uint32_t, std::uint8_t>> stack;  // node, the planes still to test (clip flags)
    if (!h->nodes.empty()) stack.push_back({0, std::uint8_t(o.frustum ? 0x3f : 0)});
    while (!stack.empty()) {
        const auto [n, mask_in] = stack.back();
        stack.pop_back();
        const HierarchyNode& node = h->nodes[n];
        // a subtree whose primitives the stages before all left out holds nothing to cull: not visited
        if (!o.candidates.empty() && candidates_below(n) == 0) continue;
        ++out.nodes_tested;
        NodeCulled e{n, NodeOutcome::partial, 0, mask_in, -1, 0, node.subtree_primitives};
        // the visibility test: the node's box against each plane the parent was not wholly inside
        for (int k = 0; k < 6 && e.plane < 0; ++k) {
            if (!(e.mask_after & (1 << k))) continue;
            ++e.planes_tested, ++out.plane_tests;
            const int side = box_side(node.box, frustum[std::size_t(k)]);
            if (side < 0) e.plane = std::int8_t(k), e.outcome = NodeOutcome::outside;
            if (side > 0) e.mask_after = std::uint8_t(e.mask_after & ~(1 << k));
        }
        if (e.outcome == NodeOutcome::outside) {
            out.outside += candidates_below(n);
            co_yield e;
            continue;
        }
        // Detail culling: too small on the screen to matter
        if (o.detail_pixels > 0 && (e.pixels = projected_pixels(node.box, camera, o.viewport_height)) < o.detail_pixels) {
            e.outcome = NodeOutcome::too_small;
            out.too_small += candidates_below(n);
            co_yield e;
            continue;
        }
        if (o.frustum && e.mask_after == 0) e.outcome = NodeOutcome::inside;
        if (!o.frustum) e.outcome = NodeOutcome::large_enough;
        if (e.outcome == NodeOutcome::inside && o.detail_pixels <= 0) {  // accepted with its subtree, no more tests
            co_yield e;
            each_below(n, [&](std::uint32_t p) { out.kept[p] = candidate(p); });
            continue;
        }
        // the node's own primitives: each box against the planes still to test (told with the node)
        for (std::uint32_t p : node.primitives) {
            if (!candidate(p)) continue;  // left out before this stage
            const bool in = box_passes(h->boxes[p], frustum, e.mask_after, &e.primitive_tests);
            ++e.own_primitives;
            out.kept[p] = in;
            out.outside += !in;
        }
        out.plane_tests += e.primitive_tests;
        co_yield e;
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.push_back({*it, e.mask_after});
    }
    std::uint32_t kept = 0;
    for (std::uint8_t k : out.kept) kept += k;
    co_yield HierarchyCullFinished{out.nodes_tested, out.plane_tests, kept, out.outside, out.too_small};
    co_return out;
}

}  // namespace hsr::algo
