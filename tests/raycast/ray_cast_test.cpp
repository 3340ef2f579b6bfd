// SPDX-License-Identifier: MIT
// Ray casting: the grid and the octree give brute force's hits; awkward rays neither divide by zero nor loop.
#include "catch.h"
#include "raycast/ray_cast.h"
#include "scene/random_scene.h"

using namespace hsr::algo;

namespace {

RayCastResult cast(const Scene& s, Viewport vp, Acceleration a, int grid_cells = 0) {
    return ray_cast(s, {.viewport = vp, .acceleration = a, .detail = RayDetail::ray, .grid_cells = grid_cells}).run_to_end();
}

// An axis-aligned square in the plane z = z0, as a polygon.
ScenePolygon square(SceneId id, double x0, double y0, double x1, double y1, double z0) {
    return {id, {}, {{x0, y0, z0, 1}, {x1, y0, z0, 1}, {x1, y1, z0, 1}, {x0, y1, z0, 1}}};
}

}  // namespace

TEST_CASE("the grid and the octree see exactly what brute force sees on random scenes", "[raycast]") {
    const Viewport vp{48, 36};
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
        const Scene s = random_triangles({.count = 60 * seed, .seed = seed, .size = 0.5 + 0.5 * seed});
        const RayCastResult brute = cast(s, vp, Acceleration::none);
        const RayCastResult grid = cast(s, vp, Acceleration::grid);
        const RayCastResult octree = cast(s, vp, Acceleration::octree);
        const RayCastResult bvh = cast(s, vp, Acceleration::bvh);
        INFO("seed " << seed);
        CHECK(bvh.polygon == brute.polygon);  // the fourth way: a BVH of axis boxes
        CHECK(bvh.t == brute.t);
        CHECK(bvh.tests < brute.tests);
        CHECK(grid.polygon == brute.polygon);
        CHECK(grid.t == brute.t);
        CHECK(octree.polygon == brute.polygon);
        CHECK(octree.t == brute.t);
        CHECK(grid.tests < brute.tests);  // the point of the grid
        CHECK(octree.tests < brute.tests);
        std::size_t seen = 0;
        for (auto p : brute.polygon) seen += p >= 0;
        CHECK(seen > brute.polygon.size() / 10);  // the scenes are not empty views
    }
}

TEST_CASE("axis-parallel rays along grid lines and through cell corners neither divide by zero nor loop", "[raycast][extremes]") {
    // An orthographic camera looking down −z: every ray is parallel to z, with direction (0, 0, −d). The squares'
    // corners sit on integer coordinates, which are grid lines of a 4-cell grid over [−2, 2], and the 8×8 pixel
    // rays of the box [−2, 2]² run through x, y = −2 + 0.25 + 0.5·i: on no line. A 4×4 viewport puts rays at
    // ±0.5 and ±1.5; shifting the box by a quarter puts them on x = −1, 0, 1: on grid lines and cell corners.
    Scene s;
    s.camera = {.projection = Projection::orthographic, .eye = {0, 0, 10}, .target = {0, 0, 0}, .near = 1, .far = 20,
                .box = {-2.25, 1.75, -1.75, 2.25}};
    s.polygons = {square(1, -2, -2, 0, 0, 0), square(2, 0, 0, 2, 2, 1), square(3, -1, -1, 1, 1, -1), square(4, -2, -2, 2, 2, -3)};
    const Viewport vp{8, 8};
    const RayCastResult brute = cast(s, vp, Acceleration::none);
    for (auto a : {Acceleration::grid, Acceleration::octree, Acceleration::bvh}) {
        const RayCastResult r = cast(s, vp, a, 4);
        CHECK(r.polygon == brute.polygon);
        CHECK(r.t == brute.t);
    }
    // The ray of pixel (4, 4) runs exactly along x = 0, y = 0: the corner of four cells, and of squares 1, 2 and 3
    const Ray corner = pixel_ray(s.camera, vp, 4, 4);
    CHECK(corner.origin.x == 0);
    CHECK(corner.origin.y == 0);
    CHECK(brute.image.id(4, 4) != 0);
}

TEST_CASE("a ray starting inside the grid starts in the eye's cell", "[raycast]") {
    Scene s = random_triangles({.count = 40, .seed = 9, .size = 1});
    s.camera.eye = {0, 0, 2};  // inside the scene's box
    s.camera.near = 0.1;
    const Viewport vp{1, 1};
    auto m = ray_cast(s, {.viewport = vp, .acceleration = Acceleration::grid, .detail = RayDetail::cell, .grid_cells = 8});
    const Grid g = build_grid([&] {
        std::vector<std::vector<Vec3>> p;
        for (const auto& q : s.polygons) p.push_back({Vec3(q.vertices[0]), Vec3(q.vertices[1]), Vec3(q.vertices[2])});
        return p;
    }(), 8);
    std::optional<CellEntered> first;
    for (const auto& e : m)
        if (const auto* c = std::get_if<CellEntered>(&e); c && !first) first = *c;
    REQUIRE(first);
    const Vec3 origin = pixel_ray(s.camera, vp, 0, 0).origin;
    const glm::ivec3 eye_cell = glm::ivec3(glm::floor((origin - g.box.lo) / g.size));
    CHECK(first->cell == eye_cell);
    CHECK(first->t_enter == 0);
}

TEST_CASE("the ray cast's step bound ends it with its own event", "[raycast][bound]") {
    const Scene s = random_triangles({.count = 20, .seed = 2});
    auto m = ray_cast(s, {.viewport = {8, 8}, .detail = RayDetail::ray, .max_tests = 50});
    RayCastEvent last = CastFinished{};
    for (const auto& e : m) last = e;
    CHECK(std::holds_alternative<CastStepBoundReached>(last));
    CHECK(std::move(m).result().bounded);
}

TEST_CASE("ray casting rejects NaN input by polygon and vertex", "[raycast][extremes]") {
    Scene s = random_triangles({.count = 3, .seed = 2});
    s.polygons[1].vertices[2].y = std::nan("");
    CHECK_THROWS_WITH(ray_cast(s, {.viewport = {4, 4}}).run_to_end(), Catch::Contains("polygon 2 vertex 2"));
}

TEST_CASE("coordinates near the double limit give a result, not undefined behaviour (found by fuzz_geometry)", "[raycast][extremes]") {
    Scene s;
    s.camera = {.eye = {0, 0, 6}, .target = {0, 0, 0}, .fov_y = 50, .near = 0.5, .far = 30};
    s.polygons.push_back({1, {}, {{-1, -1, 0, 1}, {1, -1, 0, 1}, {0, 1, 0, 1}}});
    s.polygons.push_back({2, {}, {{1e300, 0, 0, 1}, {1e300, 1, 0, 1}, {-1e300, 0, 1e-310, 1}}});
    for (const Acceleration a : {Acceleration::grid, Acceleration::octree, Acceleration::bvh}) {
        const RayCastResult r = ray_cast(s, {.viewport = {8, 6}, .acceleration = a, .detail = RayDetail::ray}).run_to_end();
        CHECK(r.image.width == 8);
    }
}
