// SPDX-License-Identifier: MIT
#include "raycast/ray_cast.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include <glm/matrix.hpp>

#include "core/numeric.h"
#include "culling/hierarchy.h"

namespace hsr::algo {
namespace {

struct Primitives {
    std::vector<std::vector<Vec3>> polygons;  // world space
    std::vector<Plane> planes;
    std::vector<std::uint32_t> scene_index;  // into the scene's polygons
};

struct Hit {
    std::int32_t index = -1;  // into Primitives
    double t = 2;             // beyond the far plane
};

struct Tally {
    std::uint64_t tests = 0, max_tests = 0;
    std::vector<std::uint64_t> mailbox;  // the ray that last tested each primitive (1, 2, …)
    std::uint64_t ray = 0;
    bool full() const { return tests >= max_tests; }
    // A primitive listed in several cells or leaves is tested once per ray (mailboxing)
    bool tested_before(std::uint32_t i) {
        if (mailbox[i] == ray) return true;
        mailbox[i] = ray;
        return false;
    }
};

// Intersect one primitive; `best` becomes it when it is hit nearer (ties to the lower index).
struct Tested {
    PrimitiveTested event;
    bool nearer;
};
Tested test(const Primitives& prims, const Scene& scene, const Ray& ray, std::uint32_t i, Hit& best, Tally& tally) {
    ++tally.tests;
    const auto t = hit(ray, prims.polygons[i], prims.planes[i]);
    const bool in_view = t && *t <= 1;
    const bool nearer = in_view && (*t < best.t || (*t == best.t && std::int32_t(i) < best.index));
    if (nearer) best = {std::int32_t(i), *t};
    const SceneId id = scene.polygons[prims.scene_index[i]].id;
    return {{prims.scene_index[i], id, in_view, in_view ? *t : 0}, nearer};
}

// The scene's polygons a ray can hit (3 or more vertices, some area), with their planes.
Primitives primitives_of(const Scene& scene) {
    Primitives prims;
    for (std::uint32_t s = 0; s < scene.polygons.size(); ++s) {
        const ScenePolygon& p = scene.polygons[s];
        std::vector<Vec3> v;
        for (std::size_t k = 0; k < p.vertices.size(); ++k) {
            require_finite(p.vertices[k], [&] { return "polygon " + std::to_string(p.id) + " vertex " + std::to_string(k); });
            v.emplace_back(p.vertices[k]);
        }
        Plane plane;
        if (v.size() < 3 || !plane_of(v, plane)) continue;  // segments and area-less polygons are never hit
        require_convex(v, p.id);  // the inside test walks the edges of a convex polygon
        prims.polygons.push_back(std::move(v));
        prims.planes.push_back(plane);
        prims.scene_index.push_back(s);
    }
    return prims;
}

NearerHitFound nearer_event(const Primitives& prims, const Scene& scene, const Hit& best) {
    const std::uint32_t s = prims.scene_index[std::size_t(best.index)];
    return {s, scene.polygons[s].id, best.t};
}

// Every primitive, as the lecture's loop has it
Steps<RayCastEvent, Hit> walk_all(const Primitives* prims, const Scene* scene, Ray ray, RayDetail detail, Tally* tally) {
    Hit best;
    for (std::uint32_t i = 0; i < prims->polygons.size() && !tally->full(); ++i) {
        const Tested r = test(*prims, *scene, ray, i, best, *tally);
        if (detail == RayDetail::test) co_yield r.event;
        if (detail == RayDetail::test && r.nearer) co_yield nearer_event(*prims, *scene, best);
    }
    co_return best;
}

// The regular grid, cell by cell along the ray (3D DDA)
Steps<RayCastEvent, Hit> walk_grid(const Grid* grid, const Primitives* prims, const Scene* scene, Ray ray,
                                   RayDetail detail, Tally* tally) {
    Hit best;
    const auto span = ray_box(ray, grid->box, 0, 1);
    if (!span) co_return best;  // the ray misses every cell
    // Start in the cell where the ray enters the grid (the eye's cell when the eye is inside)
    glm::ivec3 cell, step;
    Vec3 t_max, t_delta;
    for (int a = 0; a < 3; ++a) {
        const double o = ray.origin[a], d = ray.direction[a], entry = o + span->enter * d;
        cell[a] = grid->cell_of(entry, a);
        step[a] = d > 0 ? 1 : d < 0 ? -1 : 0;
        const double boundary = grid->box.lo[a] + (cell[a] + (d > 0 ? 1 : 0)) * grid->size[a];
        t_max[a] = d == 0 ? std::numeric_limits<double>::infinity() : (boundary - o) / d;  // next boundary on axis a
        t_delta[a] = d == 0 ? std::numeric_limits<double>::infinity() : grid->size[a] / std::abs(d);
    }
    double t_enter = span->enter;
    for (int walked = 0; walked <= grid->cells.x + grid->cells.y + grid->cells.z && !tally->full(); ++walked) {
        const double t_exit = std::min({t_max.x, t_max.y, t_max.z, span->exit});
        const auto& list = grid->at(cell);
        if (detail != RayDetail::ray) co_yield CellEntered{cell, t_enter, t_exit, std::uint32_t(list.size())};
        for (std::uint32_t i : list) {
            if (tally->tested_before(i)) continue;
            const Tested r = test(*prims, *scene, ray, i, best, *tally);
            if (detail == RayDetail::test) co_yield r.event;
            if (detail == RayDetail::test && r.nearer) co_yield nearer_event(*prims, *scene, best);
        }
        // Stop at the first hit no later cell can beat
        if ((best.index >= 0 && best.t <= t_exit) || t_exit >= span->exit) break;
        const int a = t_max.x <= t_max.y && t_max.x <= t_max.z ? 0 : t_max.y <= t_max.z ? 1 : 2;
        cell[a] += step[a];
        if (cell[a] < 0 || cell[a] >= grid->cells[a]) break;
        t_enter = t_max[a];
        t_max[a] += t_delta[a];
    }
    co_return best;
}

// The octree, children front to back, never entering a node that starts beyond the nearest hit
Steps<RayCastEvent, Hit> walk_octree(const Octree* tree, const Primitives* prims, const Scene* scene, Ray ray,
                                     RayDetail detail, Tally* tally) {
    Hit best;
    struct Visit {
        std::uint32_t node;
        Interval span;
    };
    std::vector<Visit> stack;
    if (const auto root = ray_box(ray, tree->nodes[0].box, 0, 1)) stack.push_back({0, *root});
    while (!stack.empty() && !tally->full()) {
        const Visit v = stack.back();
        stack.pop_back();
        if (best.t < v.span.enter) continue;
        const OctreeNode& node = tree->nodes[v.node];
        if (detail != RayDetail::ray)
            co_yield NodeEntered{v.node, node.depth, v.span.enter, v.span.exit, node.first_child < 0};
        for (std::uint32_t i : node.primitives) {
            if (tally->tested_before(i)) continue;
            const Tested r = test(*prims, *scene, ray, i, best, *tally);
            if (detail == RayDetail::test) co_yield r.event;
            if (detail == RayDetail::test && r.nearer) co_yield nearer_event(*prims, *scene, best);
        }
        if (node.first_child < 0) continue;
        std::array<Visit, 8> children;
        std::size_t n = 0;
        for (int c = 0; c < 8; ++c) {
            const auto child = std::uint32_t(node.first_child + c);
            if (const auto s = ray_box(ray, tree->nodes[child].box, v.span.enter, v.span.exit)) children[n++] = {child, *s};
        }
        // Push the farthest first, so the nearest is walked next
        std::sort(children.begin(), children.begin() + std::ptrdiff_t(n),
                  [](const Visit& a, const Visit& b) { return a.span.enter > b.span.enter; });
        for (std::size_t c = 0; c < n; ++c) stack.push_back(children[c]);
    }
    co_return best;
}

// A BVH: the same walk as the octree's, nearest box first, a node's box the union of its primitives' boxes (padded
// by 1e-9 of the scene's extent, so that a hit on a box face is never lost to rounding).
Steps<RayCastEvent, Hit> walk_bvh(const Hierarchy* bvh, const Primitives* prims, const Scene* scene, Ray ray, RayDetail detail, Tally* tally) {
    Hit best;
    struct Visit {
        std::uint32_t node;
        Interval span;
    };
    const Box scene_box = bounds_of(prims->polygons);
    const double pad = 1e-9 * std::max({scene_box.hi.x - scene_box.lo.x, scene_box.hi.y - scene_box.lo.y, scene_box.hi.z - scene_box.lo.z});
    const auto box_of_node = [&](std::uint32_t n) { return Box{bvh->nodes[n].box.lo - Vec3(pad), bvh->nodes[n].box.hi + Vec3(pad)}; };
    std::vector<Visit> stack;
    if (bvh->nodes.empty()) co_return best;
    if (const auto root = ray_box(ray, box_of_node(0), 0, 1)) stack.push_back({0, *root});
    while (!stack.empty() && !tally->full()) {
        const Visit v = stack.back();
        stack.pop_back();
        if (best.t < v.span.enter) continue;  // a nearer hit is known: nothing in this box can be nearer
        const HierarchyNode& node = bvh->nodes[v.node];
        if (detail != RayDetail::ray) co_yield NodeEntered{v.node, int(node.depth), v.span.enter, v.span.exit, node.children.empty()};
        for (std::uint32_t i : node.primitives) {
            const Tested r = test(*prims, *scene, ray, i, best, *tally);
            if (detail == RayDetail::test) co_yield r.event;
            if (detail == RayDetail::test && r.nearer) co_yield nearer_event(*prims, *scene, best);
        }
        std::vector<Visit> children;
        for (const std::uint32_t c : node.children)
            if (const auto s = ray_box(ray, box_of_node(c), v.span.enter, v.span.exit)) children.push_back({c, *s});
        std::sort(children.begin(), children.end(), [](const Visit& a, const Visit& b) { return a.span.enter > b.span.enter; });
        stack.insert(stack.end(), children.begin(), children.end());  // the farthest first, so the nearest is walked next
    }
    co_return best;
}

Hierarchy bvh_over(const std::vector<std::vector<Vec3>>& polygons) {
    std::vector<Aabb> boxes;
    for (const auto& p : polygons) boxes.push_back(aabb_of(p));
    return build_hierarchy(std::move(boxes), {.kind = HierarchyKind::bvh, .max_primitives = 4}).run_to_end();
}

}  // namespace

Hierarchy ray_cast_bvh(const Scene& scene) { return bvh_over(primitives_of(scene).polygons); }

Grid ray_cast_grid(const Scene& scene, int cells) { return build_grid(primitives_of(scene).polygons, cells); }

Ray pixel_ray(const Camera& camera, Viewport viewport, int x, int y) {
    return ndc_ray(camera, 2 * pixel_centre(x) / viewport.width - 1, 1 - 2 * pixel_centre(y) / viewport.height);
}

Ray ndc_ray(const Camera& camera, double nx, double ny) {
    const glm::dmat4 inverse = glm::inverse(view_projection(camera));
    const glm::dvec4 n = inverse * glm::dvec4(nx, ny, -1, 1), f = inverse * glm::dvec4(nx, ny, 1, 1);
    const Vec3 near = Vec3(n) / n.w, far = Vec3(f) / f.w;
    return {near, far - near};
}

Steps<RayCastEvent, RayCastResult> ray_cast(Scene scene, RayCastOptions o) {
    if (scene.coordinates != Coordinates::world) throw InvalidInput(scene.source + ": ray casting needs world coordinates");
    const auto prims = std::make_unique<Primitives>(primitives_of(scene));
    const auto grid = std::make_unique<Grid>(o.acceleration == Acceleration::grid ? build_grid(prims->polygons, o.grid_cells) : Grid{});
    const auto tree = std::make_unique<Octree>();
    if (o.acceleration == Acceleration::octree) {  // BuildOctree first, its cells told when the rays are
        auto build = octree_build(prims->polygons, o.octree);
        for (const auto& e : build)
            if (o.detail != RayDetail::ray) co_yield e;
        *tree = std::move(build).result();
    }

    const auto bvh = std::make_unique<Hierarchy>(o.acceleration == Acceleration::bvh ? bvh_over(prims->polygons) : Hierarchy{});

    const int w = o.viewport.width, h = o.viewport.height;
    RayCastResult out{Image(w, h, o.background), std::vector<std::int32_t>(std::size_t(w) * std::size_t(h), -1),
                      std::vector<double>(std::size_t(w) * std::size_t(h), 2.0)};
    Tally tally{0, o.max_tests, std::vector<std::uint64_t>(prims->polygons.size(), 0), 0};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Ray ray = pixel_ray(scene.camera, o.viewport, x, y);
            ++tally.ray;
            if (o.detail != RayDetail::ray) co_yield RayStarted{x, y, ray.origin, ray.direction};
            const std::uint64_t before = tally.tests;
            auto walk = o.acceleration == Acceleration::grid     ? walk_grid(grid.get(), prims.get(), &scene, ray, o.detail, &tally)
                        : o.acceleration == Acceleration::octree ? walk_octree(tree.get(), prims.get(), &scene, ray, o.detail, &tally)
                        : o.acceleration == Acceleration::bvh    ? walk_bvh(bvh.get(), prims.get(), &scene, ray, o.detail, &tally)
                                                                 : walk_all(prims.get(), &scene, ray, o.detail, &tally);
            for (const auto& e : walk) co_yield e;
            const Hit best = std::move(walk).result();
            if (tally.full()) {  // the step bound: this ray's answer may be incomplete
                out.bounded = true, out.tests = tally.tests;
                co_yield CastStepBoundReached{o.max_tests};
                co_return out;
            }
            // The pixel sees the nearest primitive
            const std::size_t k = std::size_t(y) * std::size_t(w) + std::size_t(x);
            SceneId id = 0;
            if (best.index >= 0) {
                const ScenePolygon& p = scene.polygons[prims->scene_index[std::size_t(best.index)]];
                id = p.id;
                out.polygon[k] = std::int32_t(prims->scene_index[std::size_t(best.index)]);
                out.t[k] = best.t;
                out.image.ids[k] = id;
                out.image.rgb[3 * k] = p.color.r, out.image.rgb[3 * k + 1] = p.color.g, out.image.rgb[3 * k + 2] = p.color.b;
            }
            co_yield RayFinished{x, y, out.polygon[k], id, best.t, std::uint32_t(tally.tests - before)};
        }
    out.tests = tally.tests;
    co_yield CastFinished{std::uint64_t(w) * std::uint64_t(h), tally.tests};
    co_return out;
}

}  // namespace hsr::algo
