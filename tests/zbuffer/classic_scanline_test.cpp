// SPDX-License-Identifier: MIT
// The classic scan-line algorithm (no z-buffer; the planes compared where spans begin) against a brute-force
// reference: per pixel, every polygon covering it and the nearest by its plane there. Without its extra
// intersections it paints what the notes' form paints, wrong where polygons pierce each other.
#include <cmath>

#include "catch.h"
#include "scene/random_scene.h"
#include "zbuffer/classic_scanline.h"

using namespace hsr::algo;

namespace {

double depth_at(const ScreenPolygon& p, int x, int y) { return p.plane.at(pixel_centre(x), pixel_centre(y)); }

// Per pixel, the index of the nearest polygon whose span covers it (lower index on a tie), −1 for background.
std::vector<std::int32_t> nearest_per_pixel(const std::vector<ScreenPolygon>& polygons, Viewport vp) {
    std::vector<std::int32_t> owner(std::size_t(vp.width) * std::size_t(vp.height), -1);
    for (int y = 0; y < vp.height; ++y)
        for (std::size_t p = 0; p < polygons.size(); ++p) {
            if (polygons[p].status != ScreenStatus::drawn) continue;
            const Span s = span_on_row(polygons[p], y, vp);
            for (int x = s.begin; x < s.end; ++x) {
                std::int32_t& o = owner[std::size_t(y) * std::size_t(vp.width) + std::size_t(x)];
                if (o < 0 || depth_at(polygons[p], x, y) < depth_at(polygons[std::size_t(o)], x, y)) o = std::int32_t(p);
            }
        }
    return owner;
}

// Pixels where the machine's owner is not the reference's, beyond a depth tie (both planes within 1e-12 there).
int unexplained(const std::vector<ScreenPolygon>& polygons, Viewport vp, const std::vector<std::int32_t>& got,
                const std::vector<std::int32_t>& want) {
    int n = 0;
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x) {
            const std::size_t k = std::size_t(y) * std::size_t(vp.width) + std::size_t(x);
            if (got[k] == want[k]) continue;
            if (got[k] >= 0 && want[k] >= 0 &&
                std::abs(depth_at(polygons[std::size_t(got[k])], x, y) - depth_at(polygons[std::size_t(want[k])], x, y)) <= 1e-12)
                continue;
            ++n;
        }
    return n;
}

int differing(const std::vector<std::int32_t>& a, const std::vector<std::int32_t>& b) {
    int n = 0;
    for (std::size_t k = 0; k < a.size(); ++k) n += a[k] != b[k];
    return n;
}

FrameDepth classic(const Scene& s, Viewport vp, bool find_piercings = true) {
    return classic_scan_line(project_polygons(s, vp), {.line = scan_line_options(s, vp, DepthFormat::int24), .find_piercings = find_piercings})
        .run_to_end();
}

}  // namespace

TEST_CASE("the classic scan line sees at every pixel the nearest polygon covering it", "[scanline][classic]") {
    const auto [size, near] = GENERATE(table<double, double>({{1.5, 0.5}, {3.0, 1.0}, {0.3, 0.1}, {5.0, 2.0}}));
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
        const Scene s = random_triangles({.count = 80, .seed = seed, .size = size, .near = near, .far = 50});
        const Viewport vp{97, 61};
        const auto screen = project_polygons(s, vp);
        const FrameDepth f = classic(s, vp);
        INFO("size " << size << ", seed " << seed);
        CHECK_FALSE(f.bounded);
        CHECK(unexplained(screen, vp, f.polygon, nearest_per_pixel(screen, vp)) == 0);
        // the colours and ids are the owner's
        for (std::size_t k = 0; k < f.polygon.size(); ++k)
            if (f.polygon[k] >= 0) REQUIRE(f.image.ids[k] == screen[std::size_t(f.polygon[k])].id);
            else REQUIRE(f.image.ids[k] == 0);
    }
}

TEST_CASE("without the extra intersections the notes' form is wrong exactly where polygons pierce", "[scanline][classic]") {
    // Two large triangles through each other: along each line their depths cross once.
    Scene s = random_triangles({.count = 2, .seed = 1, .size = 1});
    s.polygons[0].vertices = {{-3, -2, -2, 1}, {3, -2, 2, 1}, {0, 3, 0, 1}};
    s.polygons[1].vertices = {{-3, -2, 2, 1}, {3, -2, -2, 1}, {0, 3, 0.5, 1}};
    const Viewport vp{64, 48};
    const auto screen = project_polygons(s, vp);
    const auto reference = nearest_per_pixel(screen, vp);
    const FrameDepth with = classic(s, vp, true), without = classic(s, vp, false);
    CHECK(unexplained(screen, vp, with.polygon, reference) == 0);
    const int wrong = differing(without.polygon, reference);
    CHECK(wrong > 100);  // half of the nearer triangle's far side
    // and each wrong pixel lies beyond a piercing the full machine found on its line, on the side it switched to
    auto m = classic_scan_line(screen, {.line = scan_line_options(s, vp, DepthFormat::int24)});
    std::vector<std::vector<PiercingFound>> by_line(std::size_t(vp.height));
    for (const auto& e : m)
        if (const auto* p = std::get_if<PiercingFound>(&e)) by_line[std::size_t(p->y)].push_back(*p);
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x) {
            const std::size_t k = std::size_t(y) * std::size_t(vp.width) + std::size_t(x);
            if (without.polygon[k] == reference[k]) continue;
            INFO("pixel " << x << ", " << y);
            REQUIRE(by_line[std::size_t(y)].size() == 1);
            const PiercingFound& p = by_line[std::size_t(y)].front();
            CHECK(x >= p.pixel);
            CHECK(reference[k] == p.now);
            CHECK(std::abs(p.x - (p.pixel - 0.5)) <= 1.0);  // the planes meet within the pixel before the switch
            const ScreenPolygon &a = screen[std::size_t(p.was)], &b = screen[std::size_t(p.now)];
            CHECK(std::abs(a.plane.at(p.x, pixel_centre(y)) - b.plane.at(p.x, pixel_centre(y))) < 1e-12);
        }
}

TEST_CASE("the classic scan line compares depths only where spans begin", "[scanline][classic]") {
    const Scene s = random_triangles({.count = 60, .seed = 3, .size = 2.5});
    const Viewport vp{320, 240};  // spans many pixels long, as on a screen
    const auto screen = project_polygons(s, vp);
    std::uint64_t compared = 0, spans = 0, covered_twice = 0;
    auto m = classic_scan_line(screen, {.line = scan_line_options(s, vp, DepthFormat::int24)});
    for (const auto& e : m) {
        if (const auto* c = std::get_if<DepthsCompared>(&e)) {
            ++compared;
            CHECK(c->in >= 2);
            CHECK(c->depth <= c->next_depth);
            CHECK(c->x == std::floor(c->x) + 0.5);  // at a pixel centre
        }
        spans += std::holds_alternative<SpanColored>(e);
    }
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x) {
            int covering = 0;
            for (const auto& p : screen)
                if (p.status == ScreenStatus::drawn) {
                    const Span sp = span_on_row(p, y, vp);
                    covering += x >= sp.begin && x < sp.end;
                }
            covered_twice += covering >= 2;
        }
    CHECK(compared > 0);
    CHECK(compared <= spans);
    CHECK(compared * 3 < covered_twice);  // a per-pixel z-test would compare at every one of them
}

TEST_CASE("the edge table's fields: x on the first line, y_max, and Δx stepping to every line", "[scanline][classic]") {
    const Scene s = random_triangles({.count = 30, .seed = 7, .size = 3});
    const Viewport vp{50, 40};
    const auto screen = project_polygons(s, vp);
    const auto et = edge_table(screen, vp);
    REQUIRE(et.size() > 20);
    for (const EdgeEntry& e : et) {
        const EdgeFields f = edge_fields(e);
        CHECK(f.y_max == e.end_row - 1);
        for (int y = e.first_row; y < e.end_row; ++y)
            REQUIRE(f.x + f.dx * (y - e.first_row) == Approx(edge_x_at_row(e.a, e.b, y)).margin(1e-9));
    }
}

TEST_CASE("the classic scan line's step bound ends it with its own event", "[scanline][classic][bound]") {
    const Scene s = random_triangles({.count = 30, .seed = 5, .size = 2});
    const Viewport vp{40, 30};
    ScanLineOptions o = scan_line_options(s, vp, DepthFormat::int24);
    o.max_crossings = 25;
    auto m = classic_scan_line(project_polygons(s, vp), {.line = o});
    ScanLineEvent last = ScanFinished{};
    std::size_t events = 0;
    for (const auto& e : m) last = e, ++events;
    CHECK(std::holds_alternative<ScanStepBoundReached>(last));
    CHECK(std::move(m).result().bounded);
    CHECK(events < 400);
}

TEST_CASE("the classic scan line on extreme depths: a near plane 1e-9 from the eye, and an orthographic camera", "[scanline][classic]") {
    for (const bool orthographic : {false, true}) {
        Scene s = random_triangles({.count = 60, .seed = 9, .size = 2.5, .near = 1e-9, .far = 1e9});
        if (orthographic) {
            s.camera.projection = Projection::orthographic, s.camera.near = 1, s.camera.far = 30;
            s.camera.box[0] = -5, s.camera.box[1] = 5, s.camera.box[2] = -4, s.camera.box[3] = 4;
        }
        const Viewport vp{64, 48};
        const auto screen = project_polygons(s, vp);
        const FrameDepth f = classic(s, vp);
        INFO((orthographic ? "orthographic" : "perspective, far/near 1e18"));
        CHECK(unexplained(screen, vp, f.polygon, nearest_per_pixel(screen, vp)) == 0);
    }
}
