// SPDX-License-Identifier: MIT
// The z-buffer's visible polygon per pixel against the double-precision ray cast. Where they differ, the test
// says why, and only two reasons are allowed:
//   z-fighting  the two surfaces' depths at the pixel fall within one code of the format (the lesson's subject)
//   edge        the pixel centre lies within 0.01 pixel of an edge of either polygon on the screen, where the
//               z-buffer's 1/256-pixel snapped vertices and the ray's exact ones may disagree
#include <cmath>

#include "catch.h"
#include "raycast/ray_cast.h"
#include "scene/random_scene.h"
#include "zbuffer/zbuffer_fill.h"

using namespace hsr::algo;

namespace {

struct Disagreement {
    std::size_t z_fighting = 0, edge = 0, unexplained = 0;
};

// The window depth of polygon p where the ray of pixel (x, y) meets its plane.
double depth_on_ray(const Scene& s, Viewport vp, int x, int y, const ScenePolygon& p) {
    const Ray ray = pixel_ray(s.camera, vp, x, y);
    std::vector<Vec3> v;
    for (const auto& q : p.vertices) v.emplace_back(q);
    Plane plane;
    plane_of(v, plane);
    const double t = -plane.distance(ray.origin) / glm::dot(plane.n, ray.direction);
    const glm::dvec4 c = view_projection(s.camera) * glm::dvec4(ray.origin + t * ray.direction, 1);
    return (c.z / c.w + 1) / 2;
}

double distance_to_edges(const ScreenPolygon& p, double px, double py) {
    double best = 1e300;
    for (std::size_t i = 0, j = p.vertices.size() - 1; i < p.vertices.size(); j = i++) {
        const glm::dvec2 a(double(p.vertices[j].x) / subpixels, double(p.vertices[j].y) / subpixels);
        const glm::dvec2 b(double(p.vertices[i].x) / subpixels, double(p.vertices[i].y) / subpixels);
        const glm::dvec2 ab = b - a, ap = glm::dvec2(px, py) - a;
        const double h = std::clamp(glm::dot(ap, ab) / glm::dot(ab, ab), 0.0, 1.0);
        best = std::min(best, glm::length(ap - h * ab));
    }
    return best;
}

Disagreement compare(const Scene& s, Viewport vp, DepthFormat format) {
    const auto screen = project_polygons(s, vp);
    const FrameDepth z = zbuffer_fill(screen, zbuffer_options(s, vp, format, EventDetail::polygon)).run_to_end();
    const RayCastResult r = ray_cast(s, {.viewport = vp, .acceleration = Acceleration::grid, .detail = RayDetail::ray}).run_to_end();
    const DepthRange range{s.camera.near, s.camera.far};
    Disagreement d;
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x) {
            const std::size_t k = std::size_t(y * vp.width + x);
            const std::int32_t a = z.polygon[k], b = r.polygon[k];  // both index the scene's polygons
            if (a == b) continue;
            const bool near_edge = (a >= 0 && distance_to_edges(screen[std::size_t(a)], x + 0.5, y + 0.5) < 0.01) ||
                                   (b >= 0 && distance_to_edges(screen[std::size_t(b)], x + 0.5, y + 0.5) < 0.01);
            if (near_edge) {
                ++d.edge;
                continue;
            }
            if (a >= 0 && b >= 0) {
                const auto ca = code_of_window_depth(format, depth_on_ray(s, vp, x, y, s.polygons[std::size_t(a)]), range);
                const auto cb = code_of_window_depth(format, depth_on_ray(s, vp, x, y, s.polygons[std::size_t(b)]), range);
                if ((ca > cb ? ca - cb : cb - ca) <= 1) {
                    ++d.z_fighting;
                    continue;
                }
            }
            ++d.unexplained;
            UNSCOPED_INFO("pixel (" << x << ", " << y << "): z-buffer sees " << a << ", ray cast " << b);
        }
    return d;
}

}  // namespace

TEST_CASE("the z-buffer sees what the ray cast sees, but for z-fighting and sub-pixel edge pixels", "[zbuffer][raycast][reference]") {
    const Viewport vp{160, 120};
    const auto [format, near, far] = GENERATE(table<DepthFormat, double, double>({
        {DepthFormat::int24, 2, 20},  // near/far from 1/10 …
        {DepthFormat::int24, 1, 20},
        {DepthFormat::int16, 1, 20},
        {DepthFormat::int16, 0.01, 1000},  // a wide range: 16 bits fight
        {DepthFormat::float32, 0.1, 100},
        {DepthFormat::float32_reversed, 0.001, 1e4},
        {DepthFormat::linear24, 1, 20},
        {DepthFormat::int32, 1e-3, 1e4},  // … to 1/10^7
    }));
    std::size_t pixels = 0, fights = 0, edges = 0;
    for (std::uint32_t seed = 1; seed <= 3; ++seed) {
        const Scene s = random_triangles({.count = 80, .seed = seed, .size = 1.5, .near = near, .far = far});
        const Disagreement d = compare(s, vp, format);
        INFO(to_string(format) << ", near " << near << ", far " << far << ", seed " << seed);
        CHECK(d.unexplained == 0);
        pixels += std::size_t(vp.width * vp.height), fights += d.z_fighting, edges += d.edge;
    }
    INFO(to_string(format) << ": " << fights << " z-fighting and " << edges << " edge pixels of " << pixels);
    CHECK(edges < pixels / 200);
    CHECK(fights < pixels / 20);
}

TEST_CASE("16 bits over near/far = 1/100000 fight where 24 bits do not", "[zbuffer][reference][z-fighting]") {
    // Two squares 0.05 apart at eye distance 50, filling the view. One 16-bit code there spans
    // resolvable_step(int16, 50) ≈ 3.8 world units, so the planes share codes; one 24-bit code spans 0.015.
    Scene s;
    s.camera = {.eye = {0, 0, 50}, .target = {0, 0, 0}, .near = 0.01, .far = 1000};
    s.polygons = {{1, {255, 0, 0}, {{-40, -40, 0, 1}, {40, -40, 0, 1}, {40, 40, 0, 1}, {-40, 40, 0, 1}}},
                  {2, {0, 0, 255}, {{-40, -40, 0.05, 1}, {40, -40, 0.05, 1}, {40, 40, 0.05, 1}, {-40, 40, 0.05, 1}}}};
    const Viewport vp{32, 32};
    const Disagreement d16 = compare(s, vp, DepthFormat::int16);
    const Disagreement d24 = compare(s, vp, DepthFormat::int24);
    CHECK(d16.unexplained == 0);
    CHECK(d16.z_fighting > 900);  // of 1024: the far square, drawn first, shows through the near one
    CHECK(d24.z_fighting == 0);
    CHECK(d24.unexplained == 0);
    CHECK(resolvable_step(DepthFormat::int16, 50, {0.01, 1000}) > 0.05);
    CHECK(resolvable_step(DepthFormat::int24, 50, {0.01, 1000}) < 0.05);
}
