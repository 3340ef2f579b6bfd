// SPDX-License-Identifier: MIT
// The z-buffer fill: the top-left rule on shared edges, clipping before the divide, extremes, and the events.
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>

#include "catch.h"
#include "core/numeric.h"
#include "zbuffer/zbuffer_fill.h"

using namespace hsr::algo;

namespace {

// A triangle given straight in clip space with w = 1 (so NDC = clip), at a constant depth z.
ScreenPolygon ndc_triangle(SceneId id, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, double z, Viewport vp) {
    return project_polygon(id, {}, {{a, z, 1}, {b, z, 1}, {c, z, 1}}, vp);
}

FrameDepth fill(std::vector<ScreenPolygon> polys, Viewport vp, EventDetail detail = EventDetail::polygon) {
    return zbuffer_fill(std::move(polys), {.viewport = vp, .format = DepthFormat::float32, .detail = detail})
        .run_to_end();
}

// How many polygons cover each pixel: fill each alone and count.
std::vector<int> coverage_counts(const std::vector<ScreenPolygon>& polys, Viewport vp) {
    std::vector<int> count(std::size_t(vp.width * vp.height), 0);
    for (const auto& p : polys) {
        const FrameDepth f = fill({p}, vp);
        for (std::size_t k = 0; k < count.size(); ++k) count[k] += f.polygon[k] >= 0;
    }
    return count;
}

}  // namespace

TEST_CASE("a mesh of triangles covering the screen writes every pixel exactly once", "[zbuffer][fill-rule]") {
    const Viewport vp{37, 23};  // odd sizes, so grid lines fall between, on and across pixel centres
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.04, 0.04);
    // A 7×5 grid of jittered points spanning exactly the NDC square [-1, 1]², each cell split in two triangles
    const int nx = 7, ny = 5;
    std::vector<glm::dvec2> grid;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            const bool border_x = i == 0 || i == nx, border_y = j == 0 || j == ny;
            grid.emplace_back(-1 + 2.0 * i / nx + (border_x ? 0 : jitter(rng)), -1 + 2.0 * j / ny + (border_y ? 0 : jitter(rng)));
        }
    auto at = [&](int i, int j) { return grid[std::size_t(j * (nx + 1) + i)]; };
    std::vector<ScreenPolygon> mesh;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const bool flip = (i + j) % 2 == 1;  // both diagonals, both windings
            mesh.push_back(ndc_triangle(SceneId(mesh.size() + 1), at(i, j), at(i + 1, j), flip ? at(i, j + 1) : at(i + 1, j + 1), 0, vp));
            mesh.push_back(ndc_triangle(SceneId(mesh.size() + 1), flip ? at(i + 1, j) : at(i, j), at(i + 1, j + 1), at(i, j + 1), 0, vp));
        }
    const auto count = coverage_counts(mesh, vp);
    for (std::size_t k = 0; k < count.size(); ++k) {
        INFO("pixel (" << k % std::size_t(vp.width) << ", " << k / std::size_t(vp.width) << ")");
        REQUIRE(count[k] == 1);
    }
}

TEST_CASE("a fan around a vertex on a pixel centre gives that pixel to exactly one triangle", "[zbuffer][fill-rule]") {
    const Viewport vp{8, 8};
    // NDC (−0.125, 0.125) is the centre of pixel (3, 3) on an 8×8 viewport: every triangle has a vertex there
    const glm::dvec2 c{-0.125, 0.125};
    const std::vector<glm::dvec2> ring{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    std::vector<ScreenPolygon> fan;
    for (std::size_t i = 0; i < ring.size(); ++i)
        fan.push_back(ndc_triangle(SceneId(i + 1), c, ring[i], ring[(i + 1) % ring.size()], 0, vp));
    const auto count = coverage_counts(fan, vp);
    for (int v : count) REQUIRE(v == 1);
}

TEST_CASE("pixel centres on a left edge or on a horizontal edge below the polygon are in, OpenGL's way", "[zbuffer][fill-rule]") {
    const Viewport vp{4, 4};
    // A square from pixel centre (1.5, 1.5) to (2.5, 2.5): its left and top edges pass through centres of pixels
    // x = 1 and y = 1; its right and bottom edges through x = 2 and y = 2. OpenGL's top-left rule, applied in its
    // bottom-up row order, keeps the left and the bottom edge: only pixel (1, 2) is covered.
    const auto px = [&](double x) { return x / vp.width * 2 - 1; };
    const auto py = [&](double y) { return 1 - y / vp.height * 2; };
    const ScreenPolygon square = project_polygon(
        1, {}, {{px(1.5), py(1.5), 0, 1}, {px(2.5), py(1.5), 0, 1}, {px(2.5), py(2.5), 0, 1}, {px(1.5), py(2.5), 0, 1}}, vp);
    const FrameDepth f = fill({square}, vp);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            INFO("pixel (" << x << ", " << y << ")");
            CHECK((f.polygon[std::size_t(y * 4 + x)] == 0) == (x == 1 && y == 2));
        }
}

TEST_CASE("a triangle crossing the near plane is clipped, not discarded or wrapped", "[zbuffer][clip]") {
    Scene s;
    s.camera = {.eye = {0, 0, 0}, .target = {0, 0, -1}, .near = 1, .far = 100};
    // A floor triangle running from behind the eye (z = +5) to far ahead (z = −50)
    s.polygons.push_back({1, {255, 0, 0}, {{-3, -1, 5, 1}, {3, -1, 5, 1}, {0, -1, -50, 1}}});
    const Viewport vp{40, 40};
    const auto polys = project_polygons(s, vp);
    REQUIRE(polys[0].status == ScreenStatus::drawn);
    const FrameDepth f = fill(polys, vp);
    // It fills the bottom of the screen and nothing above the horizon (row 20)
    std::size_t bottom = 0, top = 0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x)
            if (f.polygon[std::size_t(y * 40 + x)] == 0) ++(y < 20 ? top : bottom);
    CHECK(top == 0);
    CHECK(bottom > 100);
    CHECK(f.polygon[std::size_t(39 * 40 + 20)] == 0);  // the bottom-centre pixel is the floor
}

TEST_CASE("extremes: sub-pixel, much larger than the screen, zero area, NaN", "[zbuffer][extremes]") {
    const Viewport vp{16, 16};
    SECTION("a sub-pixel triangle between pixel centres covers nothing, one around a centre covers one pixel") {
        const double p = 2.0 / 16;  // one pixel in NDC
        const FrameDepth between = fill({ndc_triangle(1, {0.1 * p, 0.1 * p}, {0.3 * p, 0.1 * p}, {0.1 * p, 0.3 * p}, 0, vp)}, vp);
        const FrameDepth around = fill({ndc_triangle(1, {0.3 * p, 0.3 * p}, {0.7 * p, 0.3 * p}, {0.5 * p, 0.7 * p}, 0, vp)}, vp);
        CHECK(between.written == 0);
        CHECK(around.written == 1);
    }
    SECTION("a triangle a million times the screen covers every pixel once") {
        const FrameDepth f = fill({ndc_triangle(1, {-1e6, -1e6}, {1e6, -1e6}, {0, 1e6}, 0.5, vp)}, vp);
        CHECK(f.written == 256);
        CHECK(f.tested == 256);
    }
    SECTION("a zero-area triangle is skipped with a reason") {
        std::vector<ScreenPolygon> polys{ndc_triangle(1, {-0.5, -0.5}, {0, 0}, {0.5, 0.5}, 0, vp)};
        CHECK(polys[0].status == ScreenStatus::zero_area);
        auto m = zbuffer_fill(std::move(polys), {.viewport = vp});
        bool skipped = false;
        for (const auto& e : m) skipped |= std::holds_alternative<PolygonSkipped>(e);
        CHECK(skipped);
        CHECK(std::move(m).result().written == 0);
    }
    SECTION("NaN input is rejected naming the polygon and vertex") {
        Scene s;
        s.polygons.push_back({4, {}, {{0, 0, 0, 1}, {1, 0, 0, 1}, {0, std::nan(""), 0, 1}}});
        CHECK_THROWS_WITH(project_polygons(s, vp), Catch::Contains("polygon 4 vertex 2"));
    }
    SECTION("a non-convex polygon is rejected by name") {
        Scene s;
        s.polygons.push_back({9, {}, {{0, 0, 0, 1}, {2, 0, 0, 1}, {1, 0.2, 0, 1}, {2, 2, 0, 1}, {0, 2, 0, 1}}});
        CHECK_THROWS_WITH(project_polygons(s, vp), Catch::Contains("polygon 9 is not convex"));
    }
}

TEST_CASE("the nearer of two overlapping polygons wins whatever the drawing order", "[zbuffer]") {
    const Viewport vp{10, 10};
    const auto near_one = ndc_triangle(1, {-1, -1}, {1, -1}, {-1, 1}, -0.5, vp);
    const auto far_one = ndc_triangle(2, {-1, -1}, {1, -1}, {-1, 1}, 0.5, vp);
    CHECK(fill({near_one, far_one}, vp).image.ids == fill({far_one, near_one}, vp).image.ids);
    CHECK(fill({far_one, near_one}, vp).image.id(1, 8) == 1);
}

TEST_CASE("event detail changes what is told, never the image", "[zbuffer][events]") {
    const Viewport vp{12, 9};
    std::vector<ScreenPolygon> polys{ndc_triangle(1, {-1, -1}, {1, -1}, {0, 1}, 0.2, vp),
                                     ndc_triangle(2, {-1, 1}, {1, 1}, {0, -1}, -0.2, vp)};
    std::size_t counts[3] = {};
    std::vector<SceneId> ids[3];
    for (EventDetail d : {EventDetail::polygon, EventDetail::span, EventDetail::pixel}) {
        auto m = zbuffer_fill(polys, {.viewport = vp, .detail = d});
        for (const auto& e : m) ++counts[int(d)], (void)e;
        ids[int(d)] = std::move(m).result().image.ids;
    }
    CHECK(counts[0] < counts[1]);
    CHECK(counts[1] < counts[2]);
    CHECK(ids[0] == ids[2]);
    CHECK(ids[1] == ids[2]);
}

TEST_CASE("each depth write carries the old and new depth and owner, so it can be undone", "[zbuffer][events]") {
    const Viewport vp{6, 6};
    std::vector<ScreenPolygon> polys{ndc_triangle(1, {-1, -1}, {1, -1}, {-1, 1}, 0.5, vp),
                                     ndc_triangle(2, {-1, -1}, {1, -1}, {-1, 1}, -0.5, vp)};
    auto m = zbuffer_fill(polys, {.viewport = vp, .format = DepthFormat::int16});
    std::vector<std::uint64_t> depth(36, far_code(DepthFormat::int16, {1, 10}));
    std::vector<std::int32_t> owner(36, -1);
    for (const auto& e : m)
        if (const auto* w = std::get_if<DepthWritten>(&e)) {
            const std::size_t k = std::size_t(w->y * 6 + w->x);
            REQUIRE(w->old_code == depth[k]);
            REQUIRE(w->old_index == owner[k]);
            depth[k] = w->new_code, owner[k] = std::int32_t(w->index);
        }
    const FrameDepth f = std::move(m).result();
    CHECK(std::vector<std::uint64_t>(f.depth.begin(), f.depth.end()) == depth);
    CHECK(f.polygon == owner);
}

TEST_CASE("the step bound ends the fill with its own event", "[zbuffer][bound]") {
    const Viewport vp{10, 10};
    auto m = zbuffer_fill({ndc_triangle(1, {-1, -1}, {1, -1}, {0, 1}, 0, vp)}, {.viewport = vp, .max_pixel_tests = 5});
    ZBufferEvent last = BufferCleared{};
    for (const auto& e : m) last = e;
    CHECK(std::holds_alternative<FillStepBoundReached>(last));
    const FrameDepth f = std::move(m).result();
    CHECK(f.bounded);
    CHECK(f.tested == 5);
    // with polygon-level events the fill takes its faster path: it stops at the same pixel, with the same buffers
    for (const std::uint64_t bound : {0u, 1u, 5u, 7u, 23u, 1000u}) {
        INFO("bound " << bound);
        const auto run = [&](EventDetail detail) {
            return zbuffer_fill({ndc_triangle(1, {-1, -1}, {1, -1}, {0, 1}, 0, vp), ndc_triangle(2, {-1, 1}, {1, 0}, {-1, -1}, 0.5, vp)},
                                {.viewport = vp, .detail = detail, .max_pixel_tests = bound})
                .run_to_end();
        };
        const FrameDepth a = run(EventDetail::pixel), b = run(EventDetail::polygon);
        CHECK(a.tested == b.tested);
        CHECK(a.written == b.written);
        CHECK(a.bounded == b.bounded);
        CHECK(a.depth == b.depth);
        CHECK(a.image.ids == b.image.ids);
    }
}

TEST_CASE("z-merge of two halves of a scene equals the z-buffer of the whole", "[zbuffer][merge]") {
    const Viewport vp{20, 20};
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.2, 1.2), z(-0.9, 0.9);
    std::vector<ScreenPolygon> a, b, all;
    for (int i = 0; i < 12; ++i) {
        const glm::dvec4 p{u(rng), u(rng), z(rng), 1}, q{u(rng), u(rng), z(rng), 1}, r{u(rng), u(rng), z(rng), 1};
        auto poly = project_polygon(SceneId(i + 1), {}, {p, q, r}, vp);
        (i % 2 ? a : b).push_back(poly);
        all.push_back(poly);
    }
    const FrameDepth merged = z_merge(fill(a, vp), fill(b, vp));
    const FrameDepth whole = fill(all, vp);
    CHECK(merged.depth == whole.depth);
    std::size_t differ = 0;  // equal depths: the whole scene keeps the first drawn, the merge takes b
    for (std::size_t k = 0; k < merged.depth.size(); ++k) differ += merged.image.ids[k] != whole.image.ids[k];
    CHECK(differ <= 2);
}

TEST_CASE("coordinates near the double limits project to a well-defined result or a clear refusal", "[zbuffer][extreme]") {
    // Found by fuzz_geometry (its input is kept as a seed): clipped at w = ε, vertices 1e306 across came out of the
    // divide far beyond [-1, 1] (rounding was all that was left), and their sub-pixel integers overflowed. The input
    // is read here as the fuzz target reads it: doubles, up to 8 polygons, before the target's camera.
    std::ifstream f(HSR_SOURCE_DIR "/tests/fuzz/corpus/geometry/regression-round-half-away-overflow", std::ios::binary);
    const std::vector<unsigned char> d((std::istreambuf_iterator<char>(f)), {});
    REQUIRE(d.size() > 100);
    std::size_t at = 0;
    const auto next = [&] {
        double v = 0;
        if (at + 8 <= d.size()) std::memcpy(&v, d.data() + at, 8), at += 8;
        return v;
    };
    Scene s;
    s.camera = {.eye = {0, 0, 6}, .target = {0, 0, 0}, .fov_y = 50, .near = 0.5, .far = 30};
    const int polygons = d[at++] % 9;
    for (int p = 0; p < polygons && at < d.size(); ++p) {
        ScenePolygon poly{SceneId(p + 1), {200, 100, 50}, {}};
        const int n = 3 + d[at++] % 4;
        for (int k = 0; k < n; ++k) {
            const double x = next(), y = next(), z = next();
            poly.vertices.emplace_back(x, y, z, 1.0);
        }
        s.polygons.push_back(std::move(poly));
    }
    const Viewport vp{64, 48};
    int projected = 0;
    for (const ScenePolygon& p : s.polygons) {
        std::vector<glm::dvec4> clip;
        for (const auto& v : p.vertices) clip.push_back(to_clip(s, v));
        try {
            for (const ScreenVertex& v : project_polygon(p.id, {}, clip, vp).vertices) {
                CHECK(v.x >= 0);
                CHECK(v.x <= 64 * subpixels);
                CHECK(v.y >= 0);
                CHECK(v.y <= 48 * subpixels);
            }
            ++projected;
        } catch (const InvalidInput& e) {
            CHECK(std::string(e.what()).find("polygon " + std::to_string(p.id)) != std::string::npos);
        }
    }
    CHECK(projected > 0);
    CHECK(round_half_away(1e300) == std::numeric_limits<long long>::min());
    CHECK(round_half_away(std::nan("")) == std::numeric_limits<long long>::min());
    CHECK(round_half_away(-2.5) == -3);
    CHECK(round_half_away(2.5) == 3);
    CHECK(round_half_away(0.49999999999999994) == 0);
}

TEST_CASE("the fill's rounding of depth codes is round_half_away's, for every value a code can take", "[zbuffer][numeric]") {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<double> xs = {0, 0.49999999999999994, 0.5, 0.5000000000000001, 1.4999999999999998, 1.5, 2.5, 4294967294.5,
                              4294967295.0, 16777214.5, 65534.5, 65535};
    for (int k = 0; k < 200000; ++k) xs.push_back(unit(rng) * (k % 3 == 0 ? 65535.0 : k % 3 == 1 ? 16777215.0 : 4294967295.0));
    for (int k = 0; k < 2000; ++k) xs.push_back(std::nextafter(double(k / 2) + 0.5, k % 2 ? 0.0 : 1e9));  // halves, one ulp off
    for (const double x : xs) {
        INFO(x);
        CHECK(round_nonnegative(x) == std::uint64_t(round_half_away(x)));
    }
}

TEST_CASE("the tiled fill of a polygon-level drain gives the machine's buffers and counts, bit for bit", "[zbuffer][binned]") {
    // detail = polygon takes binned_fill (bands of 64 rows on every core); detail = span runs the machine's own loop
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> xy(-1.2, 1.2), z(-0.9, 0.9), w(0.6, 2.5);
    for (const Viewport vp : {Viewport{200, 150}, Viewport{1100, 70}, Viewport{7, 300}}) {
        INFO(vp.width << "×" << vp.height);
        std::vector<ScreenPolygon> polys;
        for (int k = 0; k < 400; ++k) {
            std::vector<glm::dvec4> v;
            for (int i = 0; i < 3; ++i) {
                const double ww = w(rng);
                v.emplace_back(xy(rng) * ww, xy(rng) * ww, z(rng) * ww, ww);
            }
            polys.push_back(project_polygon(SceneId(k + 1), {std::uint8_t(k), 0, 0}, v, vp));
        }
        for (const DepthFormat format : {DepthFormat::int16, DepthFormat::int24, DepthFormat::float32_reversed}) {
            INFO("format " << int(format));
            const auto run = [&](EventDetail detail, std::vector<PolygonFillFinished>& finished) {
                auto m = zbuffer_fill(polys, {.viewport = vp, .format = format, .detail = detail});
                for (const auto& e : m)
                    if (const auto* f = std::get_if<PolygonFillFinished>(&e)) finished.push_back(*f);
                return std::move(m).result();
            };
            std::vector<PolygonFillFinished> a_counts, b_counts;
            const FrameDepth a = run(EventDetail::span, a_counts), b = run(EventDetail::polygon, b_counts);
            CHECK(a.depth == b.depth);
            CHECK(a.polygon == b.polygon);
            CHECK(a.image.ids == b.image.ids);
            CHECK(a.image.rgb == b.image.rgb);
            CHECK(a.tested == b.tested);
            CHECK(a.written == b.written);
            CHECK(a_counts == b_counts);
            CHECK(a.written > 1000);
        }
    }
}
