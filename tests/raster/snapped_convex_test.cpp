// SPDX-License-Identifier: MIT
// Snapping to sub-pixels must not make a convex polygon lose pixels: a short edge that turns the wrong way after
// snapping, or vertices that fall together, would let one edge's half-plane cut a wedge off its neighbour. The
// z-buffer (and the painters, which share the fill) must cover what the double-precision ray cast sees.
#include "catch.h"

#include <cmath>

#include "raycast/ray_cast.h"
#include "raster/screen_polygon.h"
#include "zbuffer/zbuffer_fill.h"

using namespace hsr::algo;

namespace {

Scene facing_camera(std::vector<glm::dvec4> vertices) {
    Scene s;
    s.camera = {.eye = {0, 0, 5}, .target = {0, 0, 0}, .fov_y = 60, .aspect = 4.0 / 3, .near = 1, .far = 20};
    s.polygons.push_back({.id = 1, .color = {200, 100, 50}, .vertices = std::move(vertices)});
    return s;
}

// Pixels whose visible polygon differs between the z-buffer and the ray cast through the same centres.
std::size_t unlike_ray_cast(const Scene& scene, Viewport vp) {
    const FrameDepth z = zbuffer_fill(project_polygons(scene, vp), zbuffer_options(scene, vp, DepthFormat::int24, EventDetail::polygon)).run_to_end();
    const RayCastResult r = ray_cast(scene, {.viewport = vp, .detail = RayDetail::ray}).run_to_end();
    std::size_t n = 0;
    for (std::size_t k = 0; k < z.image.ids.size(); ++k) n += z.image.ids[k] != r.image.ids[k];
    return n;
}

}  // namespace

TEST_CASE("a convex polygon with a sub-pixel edge keeps its wedge after snapping", "[projection][snapping]") {
    // the differential run's regression scene: a corner cut 0.001 wide, which snapping turned the wrong way
    Scene s = facing_camera({{-0.34933, 0.27012, 0, 1}, {3.0, 0.87, 0, 1}, {-3.0, 1.07, 0, 1}, {-0.350265, 0.27008000000000004, 0, 1}});
    s.camera.fov_y = 90, s.camera.aspect = 1;
    CHECK(unlike_ray_cast(s, {64, 64}) == 0);
    // the projected polygon is convex: every turn the same way
    const ScreenPolygon p = project_polygons(s, {64, 64}).front();
    REQUIRE(p.vertices.size() >= 3);
    for (std::size_t i = 0; i < p.vertices.size(); ++i) {
        const auto& a = p.vertices[i];
        const auto& b = p.vertices[(i + 1) % p.vertices.size()];
        const auto& c = p.vertices[(i + 2) % p.vertices.size()];
        CHECK((b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x) > 0);
    }
}

TEST_CASE("a dense convex polygon (a circle of many vertices) keeps its pixels", "[projection][snapping]") {
    for (const int n : {500, 5000, 30000}) {
        INFO(n << " vertices");
        std::vector<glm::dvec4> circle;
        for (int k = 0; k < n; ++k) {
            const double a = 2 * M_PI * k / n;
            circle.emplace_back(1.5 * std::cos(a), 1.5 * std::sin(a), 0, 1);
        }
        const Scene s = facing_camera(std::move(circle));
        CHECK(unlike_ray_cast(s, {128, 96}) == 0);
    }
}
