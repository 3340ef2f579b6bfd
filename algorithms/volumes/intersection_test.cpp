// SPDX-License-Identifier: MIT
#include "volumes/intersection_test.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "core/numeric.h"

namespace hsr::algo {

namespace {

constexpr double grow = 1e-9;  // relative: a volume a hair larger than its points, so rounding never loses one

double magnitude(const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// The vertices below a node, and the normals of its polygons that have a plane (for the oriented box).
void subtree_points(const BoundingModel& m, std::uint32_t node, std::vector<Vec3>& out, std::vector<Vec3>& normals) {
    const HierarchyNode& n = m.tree.nodes[node];
    for (const std::uint32_t p : n.primitives) {
        out.insert(out.end(), m.polygons[p].begin(), m.polygons[p].end());
        if (m.hittable[p]) normals.push_back(m.planes[p].n);
    }
    for (const std::uint32_t c : n.children) subtree_points(m, c, out, normals);
}

NodeVolume volume_of(std::span<const Vec3> points, std::span<const Vec3> normals, const BoundingOptions& o, bool root) {
    NodeVolume v;
    switch (o.volume) {
        case VolumeKind::aabb: {
            v.box = aabb_of(points);
            const double pad = grow * std::max(magnitude(v.box.lo), magnitude(v.box.hi));
            v.box.lo -= Vec3(pad), v.box.hi += Vec3(pad);
            v.volume = v.box.volume();
            break;
        }
        case VolumeKind::sphere:
            v.sphere = sphere_of(points);
            v.sphere.radius += grow * (v.sphere.radius + magnitude(v.sphere.centre));
            v.volume = v.sphere.volume();
            break;
        case VolumeKind::obb:
            v.obb = obb_of(points, normals);
            v.obb.half += Vec3(grow * (magnitude(v.obb.centre) + magnitude(v.obb.half)));
            v.volume = v.obb.volume();
            break;
        case VolumeKind::kdop:
        case VolumeKind::hulls:
            for (const int k : o.volume == VolumeKind::kdop ? std::vector<int>{o.k} : std::vector<int>{6, 14, 26}) {
                KDop dop = kdop_of(points, k);
                for (std::size_t i = 0; i < dop.lo.size(); ++i) {
                    const double pad = grow * std::max(std::abs(dop.lo[i]), std::abs(dop.hi[i])) * glm::length(dop.directions[i]);
                    dop.lo[i] -= pad, dop.hi[i] += pad;
                }
                if (root) v.volume = enclosed_volume(kdop_faces(dop));  // clipping out its polyhedron costs more than its tests
                v.dops.push_back(std::move(dop));
            }
            break;
    }
    return v;
}

// One ray's walk down the hierarchy: what the recursive calls share.
struct Walk {
    const BoundingModel* model;
    Ray ray;
    std::uint32_t index;
    IntersectionResult* result;
    std::uint64_t max_steps;
    std::uint32_t volume_tests = 0, primitive_tests = 0, false_alarms = 0;  // this ray's
    bool out_of_steps() {
        if (result->volume_tests + result->primitive_tests < max_steps) return false;
        result->bounded = true;
        return true;
    }
};

// LLIntersectionTest(BoundingBox(M)): the ray against the node's volume, or its hulls outermost first until one misses.
std::vector<std::pair<std::uint32_t, std::optional<Interval>>> test_volumes(const NodeVolume& v, const BoundingOptions& o, const Ray& r) {
    std::vector<std::pair<std::uint32_t, std::optional<Interval>>> tests;
    switch (o.volume) {
        case VolumeKind::aabb: tests.emplace_back(6, ray_through(v.box, r.origin, r.direction)); break;
        case VolumeKind::sphere: tests.emplace_back(0, ray_through(v.sphere, r.origin, r.direction)); break;
        case VolumeKind::obb: tests.emplace_back(0, ray_through(v.obb, r.origin, r.direction)); break;
        case VolumeKind::kdop:
        case VolumeKind::hulls:
            for (const KDop& dop : v.dops) {
                tests.emplace_back(std::uint32_t(dop.k), ray_through(dop, r.origin, r.direction));
                if (!tests.back().second) break;  // an outer hull missed: the inner ones are not tested
            }
            break;
    }
    return tests;
}

Steps<IntersectionEvent, bool> intersection_test_model(Walk* w, std::uint32_t node, std::uint32_t depth) {
    const BoundingModel& m = *w->model;
    const HierarchyNode& n = m.tree.nodes[node];
    const bool bottom = n.children.empty();
    co_yield ModelEntered{w->index, node, depth, bottom, n.subtree_primitives};
    if (bottom) {  // LLIntersectionTest(M): its primitives, one by one, until one is hit
        bool v = false;
        for (const std::uint32_t p : n.primitives) {
            if (w->out_of_steps()) co_return v;
            ++w->result->primitive_tests, ++w->primitive_tests;
            const std::optional<double> t = m.hittable[p] ? hit(w->ray, m.polygons[p], m.planes[p]) : std::nullopt;
            co_yield PrimitiveHitTested{w->index, node, p, m.ids[p], t.has_value(), t.value_or(0)};
            if (t) {
                v = true;
                break;
            }
        }
        co_yield ModelAnswered{w->index, node, v, false};
        co_return v;
    }
    bool inside = true;
    for (const auto& [k, interval] : test_volumes(m.volumes[node], m.options, w->ray)) {
        if (w->out_of_steps()) co_return false;
        ++w->result->volume_tests, ++w->volume_tests;
        co_yield VolumeTested{w->index, node, m.options.volume, k, interval.has_value(), interval ? interval->enter : 0, interval ? interval->exit : 0};
        inside = inside && interval.has_value();
    }
    if (!inside) {
        co_yield ModelAnswered{w->index, node, false, false};
        co_return false;
    }
    bool v = false;
    for (const std::uint32_t c : n.children) {
        if (v) {  // v = (v || IntersectionTest(M→C)): C is not tested
            co_yield ComponentSkipped{w->index, node, c};
            continue;
        }
        auto component = intersection_test_model(w, c, depth + 1);
        for (const auto& e : component) co_yield e;
        v = component.result();
        if (w->result->bounded) co_return v;
    }
    if (!v) ++w->result->false_alarms, ++w->false_alarms;  // the volume was met, nothing inside it was
    co_yield ModelAnswered{w->index, node, v, !v};
    co_return v;
}

}  // namespace

BoundingModel bounding_model(const Scene& scene, BoundingOptions options) {
    if (scene.coordinates != Coordinates::world) throw InvalidInput("the intersection test needs a scene in world coordinates");
    if (scene.polygons.empty()) throw InvalidInput("the intersection test needs [[polygons]] to bound: the scene has none");
    if (options.volume == VolumeKind::kdop && !valid_k(options.k)) throw InvalidInput("k: a k-DOP here has k = 6, 14, 18 or 26");
    if (options.max_primitives == 0) throw InvalidInput("max_primitives: a bottom-level model holds at least one primitive");
    BoundingModel m;
    m.options = options;
    for (const ScenePolygon& p : scene.polygons) {
        std::vector<Vec3> v;
        for (std::size_t k = 0; k < p.vertices.size(); ++k) {
            require_finite(p.vertices[k], [&] { return "polygon " + std::to_string(p.id) + " vertex " + std::to_string(k); });
            v.emplace_back(p.vertices[k]);
        }
        Plane plane;
        m.hittable.push_back(v.size() >= 3 && plane_of(v, plane));  // segments and area-less polygons are never hit
        m.planes.push_back(plane);
        m.polygons.push_back(std::move(v));
        m.ids.push_back(p.id);
    }
    m.tree = build_hierarchy(polygon_boxes(scene), {.kind = HierarchyKind::bvh, .max_primitives = options.max_primitives}).run_to_end();
    for (std::uint32_t node = 0; node < m.tree.nodes.size(); ++node) {
        std::vector<Vec3> points, normals;
        subtree_points(m, node, points, normals);
        m.volumes.push_back(volume_of(points, normals, options, node == 0));
    }
    return m;
}

Ray unit_ray(const Ray& r) {
    const Vec3 d = r.direction / magnitude(r.direction);
    return {r.origin, d / glm::length(d)};
}

std::vector<Ray> rays_of(const Scene& scene) {
    std::vector<Ray> rays;
    for (const SceneSegment& s : scene.segments) rays.push_back({Vec3(s.a), Vec3(s.b) - Vec3(s.a)});
    return rays;
}

void check_rays(const std::vector<Ray>& rays) {
    if (rays.empty()) throw InvalidInput("the intersection test needs a ray: give the scene a [[segments]] entry (from a through b)");
    for (const Ray& r : rays) {
        require_finite(glm::dvec4(r.origin, 1), "ray origin");
        require_finite(glm::dvec4(r.direction, 0), "ray direction");
        if (r.direction == Vec3(0)) throw InvalidInput("a ray's segment has a = b: it has no direction");
    }
}

Steps<IntersectionEvent, IntersectionResult> intersection_test(Scene scene, std::vector<Ray> rays, IntersectionOptions options) {
    check_rays(rays);
    const BoundingModel model = bounding_model(scene, options.bounding);
    IntersectionResult result;
    for (std::uint32_t r = 0; r < rays.size() && !result.bounded; ++r) {
        const Ray ray = unit_ray(rays[r]);
        co_yield RayStartedAt{r, ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z};
        Walk walk{&model, ray, r, &result, options.max_steps};
        auto root = intersection_test_model(&walk, 0, 0);
        for (const auto& e : root) co_yield e;
        const bool v = root.result();
        if (result.bounded) break;
        result.hits.push_back(v);
        co_yield RayAnswered{r, v, walk.volume_tests, walk.primitive_tests, walk.false_alarms};
    }
    const auto hits = std::uint32_t(std::count(result.hits.begin(), result.hits.end(), 1));
    co_yield IntersectionFinished{std::uint32_t(rays.size()), hits, result.volume_tests, result.primitive_tests, result.false_alarms,
                                  result.volume_tests + result.primitive_tests, result.bounded};
    co_return result;
}

}  // namespace hsr::algo
