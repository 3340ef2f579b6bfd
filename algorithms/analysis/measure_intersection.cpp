// SPDX-License-Identifier: MIT
// The hierarchical intersection test in the report: one scene of turned boxes (long, thin and flat ones, which axis
// boxes fit badly), one set of rays, each kind of bounding volume. The error column is the false alarms per ray (the
// price of void space); the must-be-zero count is the rays answered differently from a test of every polygon.
#include <cstdio>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "analysis/measurement.h"
#include "raycast/ray_cast.h"
#include "scene/random_scene.h"
#include "scene/generated_scenes.h"
#include "volumes/intersection_test.h"

namespace hsr::analysis {

namespace {

algo::Scene turned_boxes(int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-4, 4), thin(0.05, 0.3), long_side(0.8, 2.5), angle(0, 3.1);
    algo::Scene s;
    algo::SceneId id = 1;
    for (int b = 0; b < count; ++b) {
        const algo::Vec3 c(pos(rng), pos(rng), pos(rng));
        const algo::Vec3 half = b % 2 ? algo::Vec3(long_side(rng), thin(rng), thin(rng)) : algo::Vec3(long_side(rng), long_side(rng), thin(rng));
        const glm::dmat3 turn(glm::rotate(glm::dmat4(1), angle(rng), glm::normalize(algo::Vec3(pos(rng), pos(rng), pos(rng)) + algo::Vec3(0.1))));
        algo::add_turned_box(s, c, half, turn, {200, 200, 200}, id);
    }
    return s;
}

// Rays from a sphere of radius 14 about the scene toward random points in it.
std::vector<algo::Ray> rays(int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> gauss;
    std::uniform_real_distribution<double> pos(-4, 4);
    std::vector<algo::Ray> out;
    for (int i = 0; i < count; ++i) {
        const algo::Vec3 from = 14.0 * glm::normalize(algo::Vec3(gauss(rng), gauss(rng), gauss(rng))), to(pos(rng), pos(rng), pos(rng));
        out.push_back({from, to - from});
    }
    return out;
}

}  // namespace

std::vector<Measurement> measure_intersection(const ReportOptions& o) {
    const algo::Scene scene = turned_boxes(o.quick ? 24 : 200, 5);
    const std::vector<algo::Ray> tested = rays(o.quick ? 300 : 3000, 9);
    // the answer of a test of every polygon, the reference
    const algo::BoundingModel all = algo::bounding_model(scene, {});
    std::vector<std::uint8_t> truth;
    for (const algo::Ray& r : tested) {
        bool v = false;
        for (std::size_t p = 0; p < all.polygons.size() && !v; ++p) v = all.hittable[p] && algo::hit(r, all.polygons[p], all.planes[p]).has_value();
        truth.push_back(v);
    }
    struct Kind {
        const char* name;
        algo::BoundingOptions options;
    };
    const std::vector<Kind> kinds = {
        {"AABB", {.volume = algo::VolumeKind::aabb}},       {"sphere", {.volume = algo::VolumeKind::sphere}},
        {"OBB", {.volume = algo::VolumeKind::obb}},         {"6-DOP", {.volume = algo::VolumeKind::kdop, .k = 6}},
        {"14-DOP", {.volume = algo::VolumeKind::kdop, .k = 14}}, {"18-DOP", {.volume = algo::VolumeKind::kdop, .k = 18}},
        {"26-DOP", {.volume = algo::VolumeKind::kdop, .k = 26}}, {"progressive hulls (6, 14, 26)", {.volume = algo::VolumeKind::hulls}},
    };
    const std::vector<algo::Acceleration> accelerations = {algo::Acceleration::none, algo::Acceleration::grid, algo::Acceleration::octree,
                                                           algo::Acceleration::bvh};
    plan_runs(o, int(kinds.size() + accelerations.size()));
    const double aabb_root = algo::bounding_model(scene, kinds[0].options).volumes[0].volume;
    std::vector<Measurement> rows;
    for (const Kind& k : kinds) {
        const algo::BoundingModel model = algo::bounding_model(scene, k.options);
        algo::IntersectionResult result;
        const double ms = median_ms(o, [&] { result = algo::intersection_test(scene, tested, {.bounding = k.options}).run_to_end(); });
        std::uint64_t wrong = 0;
        for (std::size_t r = 0; r < tested.size(); ++r) wrong += result.hits[r] != truth[r];
        const double n = double(tested.size());
        char extra[200];
        std::snprintf(extra, sizeof extra, "per ray: %.2f volume tests, %.2f primitive tests; the root's volume %.2f × the AABB's; %zu nodes",
                      double(result.volume_tests) / n, double(result.primitive_tests) / n, model.volumes[0].volume / aabb_root, model.tree.nodes.size());
        rows.push_back({.family = "bounding volumes", .method = k.name,
                        .setting = std::to_string(scene.polygons.size()) + " triangles (turned boxes), " + std::to_string(tested.size()) + " rays",
                        .median_ms = ms, .error = double(result.false_alarms) / n, .error_name = "false alarms per ray",
                        .wrong = wrong, .wrong_name = "rays answered differently from every polygon tested", .wrong_must_be_zero = true, .extra = extra});
    }
    // The bounding-volume hierarchy as the fourth acceleration of ray casting, beside every primitive, the grid and
    // the octree: each pixel's nearest hit must be the one every primitive gives.
    const algo::Scene many = algo::random_triangles({.count = o.quick ? 400u : 4000u, .seed = 3, .size = o.quick ? 1.0 : 0.4});
    const algo::Viewport vp = o.quick ? algo::Viewport{64, 48} : algo::Viewport{256, 192};
    const algo::RayCastResult brute = algo::ray_cast(many, {.viewport = vp, .acceleration = algo::Acceleration::none, .detail = algo::RayDetail::ray}).run_to_end();
    for (const algo::Acceleration a : accelerations) {
        algo::RayCastResult r = brute;  // overwritten by each timed run
        const double ms = median_ms(o, [&] { r = algo::ray_cast(many, {.viewport = vp, .acceleration = a, .detail = algo::RayDetail::ray}).run_to_end(); });
        std::uint64_t differing = 0;
        for (std::size_t k = 0; k < r.polygon.size(); ++k) differing += r.polygon[k] != brute.polygon[k];
        const double tests_per_ray = double(r.tests) / double(r.polygon.size());
        rows.push_back({.family = "ray casting", .method = "ray casting: " + std::string(algo::to_string(a)),
                        .setting = std::to_string(many.polygons.size()) + " random triangles, " + std::to_string(vp.width) + "×" + std::to_string(vp.height),
                        .median_ms = ms, .error = tests_per_ray, .error_name = "primitive tests per ray",
                        .wrong = differing, .wrong_name = "pixels whose nearest hit differs from every primitive's", .wrong_must_be_zero = true});
    }
    return rows;
}

// Its sections of the report (analysis/measurement.h report_sections)
const ReportSection intersection_report{measure_intersection, {{"ray casting", "Ray casting: every primitive, the grid, the octree and the BVH, primitive tests per ray"}, {"bounding volumes", "Bounding volumes: IntersectionTest(M) per kind of volume, false alarms per ray"}}};

}  // namespace hsr::analysis
