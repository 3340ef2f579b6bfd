// SPDX-License-Identifier: MIT
// The A-buffer against independent references: each fragment's coverage against the exact area of the (snapped)
// polygon inside its pixel, within the bound a mask of m × m point samples allows (only sub-sample cells the
// boundary crosses can be wrong: at most (Δx + Δy)·m + 3 of them per boundary piece); each pixel against rays cast in
// world space, 16 × 16 per pixel, composited front to back (analysis/supersampled_rays), exactly where no edge
// crosses the pixel and within both sampling bounds where one does.
#include <algorithm>
#include <bit>
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "abuffer/a_buffer.h"
#include "analysis/supersampled_rays.h"
#include "catch.h"
#include "core/numeric.h"
#include "core/plane.h"

using namespace hsr::algo;

namespace {

constexpr Viewport grid{24, 18};
constexpr int reference_rays = 16;

Scene layered_scene(std::uint32_t seed, bool orthographic, bool translucent) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1), size(0.05, 1.2), alpha(0.25, 0.9), turn(0, 3.1);
    Scene s;
    s.camera.eye = {0, 0, 6}, s.camera.target = {0, 0, 0}, s.camera.near = 1, s.camera.far = 20, s.camera.aspect = 24.0 / 18;
    if (orthographic) {
        s.camera.projection = Projection::orthographic;
        s.camera.box[0] = -2, s.camera.box[1] = 2, s.camera.box[2] = -1.5, s.camera.box[3] = 1.5;
    }
    // quads and triangles parallel to the image plane, each at a depth of its own: one depth order everywhere
    for (int k = 0; k < 10; ++k) {
        ScenePolygon p;
        p.id = SceneId(k + 1);
        p.color = {std::uint8_t(40 + 20 * k), std::uint8_t(230 - 17 * k), std::uint8_t(90 + 13 * k)};
        p.opacity = translucent && k % 2 ? alpha(rng) : 1;
        const double z = -0.3 * k, r = k == 9 ? 0.02 : size(rng), a0 = turn(rng);  // the last one thinner than a pixel
        const Vec3 c(1.5 * u(rng), 1.1 * u(rng), z);
        const int corners = 3 + k % 2;
        for (int v = 0; v < corners; ++v) {
            const double a = a0 + 2 * 3.14159265358979 * v / corners;
            p.vertices.emplace_back(c + Vec3(r * std::cos(a), r * std::sin(a), 0), 1.0);
        }
        s.polygons.push_back(p);
    }
    return s;
}

ABufferImage run(const Scene& s, int m, Viewport vp = grid) { return a_buffer(s, vp, {.mask_size = m}).run_to_end(); }

ScreenPolygon screen(const Scene& s, std::size_t k, Viewport vp = grid) {
    std::vector<glm::dvec4> clip;
    for (const auto& v : s.polygons[k].vertices) clip.push_back(view_projection(s.camera) * v);
    return project_polygon(s.polygons[k].id, s.polygons[k].color, clip, vp);
}

std::vector<glm::dvec2> in_pixels(const ScreenPolygon& p) {
    std::vector<glm::dvec2> v;
    for (const auto& q : p.vertices) v.emplace_back(double(q.x) / subpixels, double(q.y) / subpixels);
    return v;
}

// The polygon clipped to pixel (x, y) (Sutherland–Hodgman on the square's four sides), and its area.
double area_in_pixel(std::vector<glm::dvec2> poly, int x, int y) {
    const auto cut = [&](int axis, double at, bool keep_above) {
        std::vector<glm::dvec2> out;
        for (std::size_t k = 0; k < poly.size(); ++k) {
            const glm::dvec2 a = poly[k], b = poly[(k + 1) % poly.size()];
            const bool ia = keep_above ? a[axis] >= at : a[axis] <= at, ib = keep_above ? b[axis] >= at : b[axis] <= at;
            if (ia) out.push_back(a);
            if (ia != ib) out.push_back(a + (b - a) * ((at - a[axis]) / (b[axis] - a[axis])));
        }
        poly = out;
    };
    cut(0, x, true), cut(0, x + 1, false), cut(1, y, true), cut(1, y + 1, false);
    double area = 0;
    for (std::size_t k = 0; k < poly.size(); ++k) area += poly[k].x * poly[(k + 1) % poly.size()].y - poly[(k + 1) % poly.size()].x * poly[k].y;
    return std::abs(area) / 2;
}

// How many sub-sample cells (of m × m in a pixel) the polygon's boundary can cross inside pixel (x, y): per edge
// piece inside the pixel, (Δx + Δy)·m + 3.
double crossed_cells(const std::vector<glm::dvec2>& poly, int x, int y, int m) {
    double cells = 0;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        glm::dvec2 a = poly[k], b = poly[(k + 1) % poly.size()];
        double t0 = 0, t1 = 1;  // Liang–Barsky against the pixel's square
        const double p[4] = {-(b.x - a.x), b.x - a.x, -(b.y - a.y), b.y - a.y};
        const double q[4] = {a.x - x, x + 1 - a.x, a.y - y, y + 1 - a.y};
        bool visible = true;
        for (int e = 0; e < 4 && visible; ++e) {
            if (p[e] == 0) visible = q[e] >= 0;
            else if (p[e] < 0) t0 = std::max(t0, q[e] / p[e]);
            else t1 = std::min(t1, q[e] / p[e]);
        }
        if (!visible || t0 > t1) continue;
        const glm::dvec2 d = (b - a) * (t1 - t0);
        cells += (std::abs(d.x) + std::abs(d.y)) * m + 3;
    }
    return cells;
}

double channel_error(const glm::dvec4& a, const glm::dvec4& b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z), std::abs(a.w - b.w)});
}

}  // namespace

TEST_CASE("Each fragment's coverage is the polygon's area in its pixel, within the mask's resolution", "[abuffer]") {
    for (const int m : {1, 2, 4, 8})
        for (std::uint32_t seed = 1; seed <= 4; ++seed) {
            const Scene s = layered_scene(seed, seed % 2 == 0, false);
            const ABufferImage image = run(s, m);
            std::vector<std::vector<glm::dvec2>> polys;
            for (std::size_t k = 0; k < s.polygons.size(); ++k) polys.push_back(in_pixels(screen(s, k)));
            std::size_t checked = 0;
            for (int y = 0; y < grid.height; ++y)
                for (int x = 0; x < grid.width; ++x) {
                    const auto& list = image.lists[std::size_t(y) * grid.width + std::size_t(x)];
                    for (std::size_t k = 0; k < s.polygons.size(); ++k) {
                        const auto it = std::find_if(list.begin(), list.end(), [&](const Fragment& f) { return f.polygon == k; });
                        const double coverage = it == list.end() ? 0 : double(std::popcount(it->mask)) / (m * m);
                        const double area = area_in_pixel(polys[k], x, y);
                        INFO("m " << m << ", seed " << seed << ", polygon " << k << ", pixel " << x << ", " << y);
                        CHECK(std::abs(coverage - area) <= crossed_cells(polys[k], x, y, m) / (m * m) + 1e-12);
                        ++checked;
                    }
                }
            CHECK(checked == std::size_t(grid.width * grid.height) * s.polygons.size());
        }
}

TEST_CASE("Pixels match rays cast in world space: exactly inside, within both sampling bounds on edges", "[abuffer]") {
    for (const bool translucent : {false, true})
        for (std::uint32_t seed = 1; seed <= 3; ++seed) {
            const Scene s = layered_scene(seed, seed == 3, translucent);
            const std::vector<glm::dvec4> reference = hsr::analysis::supersampled_image(s, grid, reference_rays);
            std::vector<std::vector<glm::dvec2>> polys;
            for (std::size_t k = 0; k < s.polygons.size(); ++k) polys.push_back(in_pixels(screen(s, k)));
            for (const int m : {4, 8}) {
                const ABufferImage image = run(s, m);
                std::size_t interior = 0;
                for (int y = 0; y < grid.height; ++y)
                    for (int x = 0; x < grid.width; ++x) {
                        double bound = 0;  // each polygon whose boundary crosses the pixel, sampled both ways, plus snapping
                        for (const auto& p : polys) {
                            const double a = crossed_cells(p, x, y, m), r = crossed_cells(p, x, y, reference_rays);
                            if (a > 0) bound += a / (m * m) + r / (reference_rays * reference_rays) + 0.01;
                        }
                        const double error = channel_error(image.at(x, y), reference[std::size_t(y) * grid.width + std::size_t(x)]);
                        INFO("m " << m << ", seed " << seed << (translucent ? " translucent" : " opaque") << ", pixel " << x << ", " << y);
                        if (bound == 0) {  // no edge in the pixel: the same layers at every sample, composited alike
                            CHECK(error < 1e-12);
                            ++interior;
                        } else {
                            CHECK(error <= bound);
                        }
                    }
                CHECK(interior > 100);
            }
        }
}

TEST_CASE("A finer mask is nearer the rays: the mean error falls as the mask grows", "[abuffer]") {
    double mean[4] = {};
    int at = 0;
    for (const int m : {1, 2, 4, 8}) {
        for (std::uint32_t seed = 1; seed <= 3; ++seed) {
            const Scene s = layered_scene(seed, false, true);
            const std::vector<glm::dvec4> reference = hsr::analysis::supersampled_image(s, grid, reference_rays);
            const ABufferImage image = run(s, m);
            for (std::size_t k = 0; k < reference.size(); ++k) mean[at] += channel_error(image.rgba[k], reference[k]) / double(reference.size());
        }
        ++at;
    }
    INFO("mean channel error at m = 1, 2, 4, 8: " << mean[0] << ", " << mean[1] << ", " << mean[2] << ", " << mean[3]);
    CHECK(mean[1] < mean[0]);
    CHECK(mean[2] < mean[1]);
    CHECK(mean[3] < mean[2]);
    CHECK(mean[3] < mean[0] / 3);
}

TEST_CASE("One sample per pixel is the z-buffer's coverage: the pixel centre under the fill rule", "[abuffer]") {
    const Scene s = layered_scene(5, false, false);
    const ABufferImage image = run(s, 1);
    for (std::size_t k = 0; k < s.polygons.size(); ++k) {
        const ScreenPolygon p = screen(s, k);
        for (int y = 0; y < grid.height; ++y) {
            const Span span = p.status == ScreenStatus::drawn ? span_on_row(p, y, grid) : Span{};
            for (int x = 0; x < grid.width; ++x) {
                const auto& list = image.lists[std::size_t(y) * grid.width + std::size_t(x)];
                const bool has = std::any_of(list.begin(), list.end(), [&](const Fragment& f) { return f.polygon == k; });
                CHECK(has == (x >= span.begin && x < span.end && y >= p.row_begin && y < p.row_end));
            }
        }
    }
}

TEST_CASE("A polygon thinner than a pixel: one sample misses or takes it whole, eight by eight weigh it", "[abuffer]") {
    Scene s;
    s.camera.eye = {0, 0, 5}, s.camera.near = 1, s.camera.far = 10;
    ScenePolygon p;  // a triangle of about a tenth of a pixel, off the pixel centre
    p.id = 1, p.color = {255, 255, 255};
    const Viewport vp{8, 8};
    const glm::dmat4 to_world = glm::inverse(view_projection(s.camera));
    const auto at_pixel = [&](double px, double py) {  // the point of the plane z = 0 seen at (px, py)
        const glm::dvec4 a = to_world * glm::dvec4(2 * px / vp.width - 1, 1 - 2 * py / vp.height, -1, 1);
        const glm::dvec4 b = to_world * glm::dvec4(2 * px / vp.width - 1, 1 - 2 * py / vp.height, 1, 1);
        const Vec3 from = Vec3(a) / a.w, to = Vec3(b) / b.w;
        return glm::dvec4(from + (to - from) * (-from.z / (to.z - from.z)), 1);
    };
    p.vertices = {at_pixel(3.1, 3.1), at_pixel(3.1, 3.45), at_pixel(3.45, 3.1)};
    s.polygons.push_back(p);
    const double area = 0.35 * 0.35 / 2;
    const ABufferImage one = run(s, 1, vp), eight = run(s, 8, vp);
    CHECK(one.fragments == 0);  // the centre (3.5, 3.5) is outside: the z-buffer loses it
    REQUIRE(eight.fragments == 1);
    CHECK(std::abs(eight.at(3, 3).w - area) < 3.0 / 64);
}

TEST_CASE("The A-buffer refuses a mask size it has no bits for, and stops at its step bound", "[abuffer]") {
    const Scene s = layered_scene(1, false, false);
    CHECK_THROWS_AS(run(s, 3), InvalidInput);
    CHECK_THROWS_AS(run(s, 16), InvalidInput);
    auto steps = a_buffer(s, grid, {.mask_size = 4, .max_fragments = 5});
    std::optional<ABufferFinished> finished;
    for (const auto& e : steps)
        if (const auto* f = std::get_if<ABufferFinished>(&e)) finished = *f;
    REQUIRE(finished);
    CHECK(finished->bounded);
    CHECK(finished->fragments == 5);
    CHECK(describe(ABufferEvent(*finished)).find("step bound") != std::string::npos);
}

TEST_CASE("A polygon reaching behind the eye is clipped, not wrapped: no NaN, the same as the rays", "[abuffer]") {
    Scene s;
    s.camera.eye = {0, 0, 5}, s.camera.near = 1, s.camera.far = 10;
    ScenePolygon floor;  // a floor from in front of the eye to behind it (w = 0 on the way)
    floor.id = 1, floor.color = {200, 120, 40}, floor.opacity = 0.5;
    for (const Vec3 v : {Vec3(-4, -1, -5), Vec3(4, -1, -5), Vec3(4, -1, 9), Vec3(-4, -1, 9)}) floor.vertices.emplace_back(v, 1.0);
    s.polygons.push_back(floor);
    const Viewport vp{16, 12};
    const ABufferImage image = run(s, 4, vp);
    const std::vector<glm::dvec4> reference = hsr::analysis::supersampled_image(s, vp, reference_rays);
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x) {
            const glm::dvec4 c = image.at(x, y);
            for (int k = 0; k < 4; ++k) CHECK(std::isfinite(c[k]));
            CHECK(channel_error(c, reference[std::size_t(y) * vp.width + std::size_t(x)]) < 0.3);  // one edge (the horizon) at most
        }
    CHECK(image.fragments > 0);
}
