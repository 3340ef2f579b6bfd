// SPDX-License-Identifier: MIT
// Newell's depth sort: each test decides when it should, cycles and piercing pairs end with a split and the right
// image, and on random scenes the painter's image in the final order is the ray cast's but for boundary pixels.
#include <algorithm>

#include "catch.h"
#include "analysis/painters.h"
#include "raster/image.h"
#include "depth_sort/depth_sort.h"
#include "depth_sort/front_to_back.h"
#include "raycast/ray_cast.h"
#include "scene/load_scene.h"
#include "scene/random_scene.h"

using namespace hsr::algo;

namespace {

SortPolygon poly(SceneId id, std::vector<Vec3> v) { return {id, {}, std::move(v)}; }

// A bar of width 0.16 along a segment in NDC, z linear along it: a planar quad.
SortPolygon bar(SceneId id, glm::dvec2 a, glm::dvec2 b, double za, double zb) {
    const glm::dvec2 d = glm::normalize(b - a), n(-d.y * 0.08, d.x * 0.08);
    return poly(id, {{a - n, za}, {b - n, zb}, {b + n, zb}, {a + n, za}});
}

struct Run {
    DepthSortResult result;
    std::vector<DepthSortEvent> events;
};
Run run(std::vector<SortPolygon> p, DepthSortOptions o = {}) {
    auto m = depth_sort(std::move(p), o);
    Run r;
    for (const auto& e : m) r.events.push_back(e);
    r.result = std::move(m).result();
    return r;
}

// The test that settled the first pair examined.
std::optional<OrderTest> first_decider(const Run& r) {
    for (const auto& e : r.events)
        if (const auto* t = std::get_if<TestTried>(&e); t && t->passed) return t->test;
    return std::nullopt;
}

// Paints the order into an image (NDC polygons, w = 1).
Image paint(const DepthSortResult& r, Viewport vp) {
    Image image(vp.width, vp.height);
    for (std::uint32_t i : r.order) {
        std::vector<glm::dvec4> clip;
        for (const Vec3& v : r.polygons[i].vertices) clip.emplace_back(v, 1.0);
        paint_clip_polygon(image, std::move(clip), r.polygons[i].id, {});
    }
    return image;
}

// The nearest polygon along the view ray (parallel to z in NDC) through an image point, by brute force.
SceneId seen_in_ndc(const std::vector<SortPolygon>& polys, double x, double y) {
    SceneId best = 0;
    double best_z = 2;
    for (const auto& p : polys) {
        std::vector<Vec3> v = p.vertices;
        Plane pl;
        if (!plane_of(v, pl) || pl.n.z == 0) continue;
        const Ray ray{{x, y, -1}, {0, 0, 1}};
        if (const auto t = hit(ray, v, pl); t && *t - 1 < best_z) best_z = *t - 1, best = p.id;
    }
    return best;
}

// How far, in pixels, a pixel's centre is from the nearest edge of polygon `id`'s fragments (NDC vertices; rows go
// down the image).
double pixels_to_edge(const DepthSortResult& r, SceneId id, int x, int y, Viewport vp) {
    const glm::dvec2 centre(x + 0.5, y + 0.5);
    double nearest = 1e300;
    for (const SortPolygon& p : r.polygons) {
        if (p.id != id) continue;
        for (std::size_t k = 0; k < p.vertices.size(); ++k) {
            const auto pixel = [&](const Vec3& v) { return glm::dvec2((v.x + 1) / 2 * vp.width, (1 - v.y) / 2 * vp.height); };
            const glm::dvec2 a = pixel(p.vertices[k]), b = pixel(p.vertices[(k + 1) % p.vertices.size()]);
            const glm::dvec2 ab = b - a;
            const double t = glm::dot(ab, ab) > 0 ? std::clamp(glm::dot(centre - a, ab) / glm::dot(ab, ab), 0.0, 1.0) : 0.0;
            nearest = std::min(nearest, glm::length(centre - (a + t * ab)));
        }
    }
    return nearest;
}

// Pixels whose visible polygon the ray cast and the painter's order agree on, and disagree on, leaving out
// boundary pixels (where a neighbour's ray sees something else). A disagreement where the pixel's centre is within
// 1/256 pixel of an edge of either polygon is a tie, not an error: the painter snaps vertices to 1/256 of a pixel
// (as GL does), the ray cast does not, and a sliver thinner than a pixel has no neighbour to mark its boundary.
struct Agreement {
    int compared = 0, wrong = 0, ties = 0;
};
Agreement compare_with_ray_cast(const Scene& s, const DepthSortResult& r, Viewport vp) {
    const Image image = paint(r, vp);
    const RayCastResult ref = ray_cast(s, {.viewport = vp, .detail = RayDetail::ray}).run_to_end();
    Agreement a;
    for (int y = 1; y + 1 < vp.height; ++y)
        for (int x = 1; x + 1 < vp.width; ++x) {
            const SceneId want = ref.image.id(x, y), got = image.id(x, y);
            if (ref.image.id(x + 1, y) != want || ref.image.id(x - 1, y) != want || ref.image.id(x, y + 1) != want ||
                ref.image.id(x, y - 1) != want)
                continue;
            ++a.compared;
            if (got == want) continue;
            const double snap = 1.0 / 256;
            if ((got && pixels_to_edge(r, got, x, y, vp) <= snap) || (want && pixels_to_edge(r, want, x, y, vp) <= snap)) ++a.ties;
            else ++a.wrong;
        }
    return a;
}

Scene lesson_scene(const char* name) { return load_scene(std::string(HSR_SOURCE_DIR "/assets/scenes/") + name); }

}  // namespace

TEST_CASE("each of the five tests is the one that decides, for a pair made for it", "[depth-sort]") {
    SECTION("1. x extents apart") {
        const Run r = run({poly(1, {{-0.9, -0.5, 0.6}, {-0.5, -0.5, 0.6}, {-0.7, 0.5, 0.5}}),
                           poly(2, {{0.5, -0.5, 0.55}, {0.9, -0.5, 0.55}, {0.7, 0.5, 0.55}})});
        CHECK(first_decider(r) == OrderTest::x_extents);
    }
    SECTION("2. y extents apart") {
        const Run r = run({poly(1, {{-0.5, -0.9, 0.6}, {0.5, -0.9, 0.6}, {0, -0.5, 0.5}}),
                           poly(2, {{-0.5, 0.5, 0.55}, {0.5, 0.5, 0.55}, {0, 0.9, 0.55}})});
        CHECK(first_decider(r) == OrderTest::y_extents);
    }
    SECTION("3. R wholly behind Q's plane") {  // parallel tilted planes, Q 0.2 nearer
        const Run r = run({poly(1, {{-1, -0.5, 0.6}, {0, -0.5, 0.8}, {0, 0.5, 0.8}, {-1, 0.5, 0.6}}),
                           poly(2, {{-0.5, -0.5, 0.5}, {0.5, -0.5, 0.7}, {0.5, 0.5, 0.7}, {-0.5, 0.5, 0.5}})});
        CHECK(first_decider(r) == OrderTest::r_behind_q);
        CHECK(r.result.order == std::vector<std::uint32_t>{0, 1});
    }
    SECTION("4. Q wholly in front of R's plane") {
        const Run r = run({poly(1, {{-1, -0.5, 0.6}, {0, -0.5, 0.7}, {0, 0.5, 0.7}, {-1, 0.5, 0.6}}),
                           poly(2, {{-0.3, -0.2, 0.62}, {0, -0.2, 0.62}, {0, 0.2, 0.62}, {-0.3, 0.2, 0.62}})});
        CHECK(first_decider(r) == OrderTest::q_in_front_of_r);
    }
    SECTION("5. projections apart though their boxes overlap") {
        const Run r = run({poly(1, {{-1, -1, 0.3}, {0.2, -1, 0.54}, {-1, 0.2, 0.3}}),
                           poly(2, {{1, 1, 0.7}, {-0.2, 1, 0.7}, {1, -0.2, 0.46}})});
        CHECK(first_decider(r) == OrderTest::projections);
        std::vector<OrderTest> tried;
        for (const auto& e : r.events)
            if (const auto* t = std::get_if<TestTried>(&e)) tried.push_back(t->test);
        CHECK(tried == std::vector<OrderTest>{OrderTest::x_extents, OrderTest::y_extents, OrderTest::r_behind_q,
                                              OrderTest::q_in_front_of_r, OrderTest::projections});
    }
    SECTION("the swapped test 3 moves Q to the head of the list") {
        // R (head, farthest MAXZ) is a tilted plane whose near end lies in front of Q; Q lies wholly behind it
        const Run r = run({poly(1, {{-1, -0.5, 0.2}, {1, -0.5, 0.9}, {1, 0.5, 0.9}, {-1, 0.5, 0.2}}),
                           poly(2, {{-0.9, -0.3, 0.8}, {-0.5, -0.3, 0.8}, {-0.5, 0.3, 0.8}, {-0.9, 0.3, 0.8}})});
        bool moved = false;
        for (const auto& e : r.events) moved |= std::holds_alternative<PolygonMoved>(e);
        CHECK(moved);
        CHECK(r.result.order == std::vector<std::uint32_t>{1, 0});
    }
}

TEST_CASE("three bars in a cyclic overlap end with a split and the right image", "[depth-sort]") {
    // B lies over A, C over B, and A over C: no order of the three is right
    const std::vector<SortPolygon> bars = {bar(1, {-0.8, -0.5}, {0.8, -0.5}, 0.3, 0.7),
                                           bar(2, {0.7, -0.8}, {-0.1, 0.8}, 0.3, 0.7),
                                           bar(3, {0.1, 0.8}, {-0.7, -0.8}, 0.3, 0.7)};
    const Run r = run(bars);
    CHECK(r.result.splits >= 1);
    CHECK_FALSE(r.result.bounded);
    const Viewport vp{64, 64};
    const Image image = paint(r.result, vp);
    int compared = 0;
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x) {
            const double nx = (x + 0.5) / vp.width * 2 - 1, ny = 1 - (y + 0.5) / vp.height * 2, e = 0.02;
            const SceneId want = seen_in_ndc(bars, nx, ny);
            if (seen_in_ndc(bars, nx + e, ny) != want || seen_in_ndc(bars, nx - e, ny) != want ||
                seen_in_ndc(bars, nx, ny + e) != want || seen_in_ndc(bars, nx, ny - e) != want)
                continue;  // a boundary pixel
            ++compared;
            INFO("pixel (" << x << ", " << y << ")");
            REQUIRE(image.id(x, y) == want);
        }
    CHECK(compared > 500);
    SECTION("with no splits allowed it stops at the bound, naming it") {
        const Run bounded = run(bars, {.max_splits = 0});
        CHECK(bounded.result.bounded);
        CHECK(std::holds_alternative<SortBoundReached>(bounded.events.back()));
    }
}

TEST_CASE("two piercing polygons end with a split and the right order", "[depth-sort]") {
    const std::vector<SortPolygon> pair = {poly(1, {{-0.8, -0.6, 0.3}, {0.8, -0.6, 0.7}, {0, 0.7, 0.5}}),
                                           poly(2, {{-0.8, 0.6, 0.7}, {0.8, 0.6, 0.3}, {0, -0.7, 0.5}})};
    const Run r = run(pair);
    CHECK(r.result.splits >= 1);
    const Image image = paint(r.result, {40, 40});
    CHECK(image.id(8, 20) == seen_in_ndc(pair, (8.5 / 40) * 2 - 1, 0));
    CHECK(image.id(32, 20) == seen_in_ndc(pair, (32.5 / 40) * 2 - 1, 0));
}

TEST_CASE("painting in the depth-sorted order gives the ray cast's image on random scenes", "[depth-sort][reference]") {
    const Projection projection = GENERATE(Projection::perspective, Projection::orthographic);
    for (std::uint32_t seed = 1; seed <= 3; ++seed) {
        Scene s = random_triangles({.count = 40, .seed = seed, .size = 1.2});
        s.camera.projection = projection;
        s.camera.box[0] = -6, s.camera.box[1] = 6, s.camera.box[2] = -6, s.camera.box[3] = 6;
        const Viewport vp{64, 64};
        const Run r = run(sort_polygons(s));
        REQUIRE_FALSE(r.result.bounded);
        const auto [compared, wrong, ties] = compare_with_ray_cast(s, r.result, vp);
        INFO("seed " << seed << ", " << (projection == Projection::perspective ? "perspective" : "orthographic"));
        CHECK(compared > 1000);
        CHECK(wrong == 0);
        CHECK(ties <= 2);  // (seed 2, perspective: one, a sliver's edge 1e-4 pixel from a pixel's centre)
    }
}

TEST_CASE("depth sort extremes: shared edges, coplanar overlaps, edge-on polygons, NaN", "[depth-sort][extremes]") {
    SECTION("coplanar overlapping squares are drawn, no split") {
        const Run r = run({poly(1, {{-0.5, -0.5, 0.5}, {0.3, -0.5, 0.5}, {0.3, 0.3, 0.5}, {-0.5, 0.3, 0.5}}),
                           poly(2, {{-0.3, -0.3, 0.5}, {0.5, -0.3, 0.5}, {0.5, 0.5, 0.5}, {-0.3, 0.5, 0.5}})});
        CHECK(r.result.order.size() == 2);
        CHECK(r.result.splits == 0);
    }
    SECTION("a polygon seen edge-on (the viewpoint in its plane) is drawn, no split") {
        const Run r = run({poly(1, {{-0.5, 0, 0.2}, {0.5, 0, 0.2}, {0.5, 0, 0.8}, {-0.5, 0, 0.8}}),
                           poly(2, {{-0.5, -0.5, 0.5}, {0.5, -0.5, 0.5}, {0, 0.5, 0.5}})});
        CHECK(r.result.order.size() == 2);
        CHECK(r.result.splits == 0);
    }
    SECTION("a mesh sharing edges needs no split") {
        Scene s;
        s.camera = {.eye = {0, 0, 5}, .near = 1, .far = 10};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                const double x = i - 2, y = j - 2, z = 0.1 * (i + j);
                s.polygons.push_back({SceneId(2 * (i * 4 + j) + 1), {}, {{x, y, z, 1}, {x + 1, y, z + 0.1, 1}, {x + 1, y + 1, z + 0.2, 1}}});
                s.polygons.push_back({SceneId(2 * (i * 4 + j) + 2), {}, {{x, y, z, 1}, {x + 1, y + 1, z + 0.2, 1}, {x, y + 1, z + 0.1, 1}}});
            }
        const Run r = run(sort_polygons(s));
        CHECK(r.result.order.size() == 32);
        CHECK(r.result.splits == 0);
    }
    SECTION("NaN is rejected by polygon and vertex") {
        Scene s;
        s.polygons.push_back({7, {}, {{0, 0, 0, 1}, {1, 0, 0, 1}, {0, std::nan(""), 0, 1}}});
        CHECK_THROWS_WITH(sort_polygons(s), Catch::Contains("polygon 7 vertex 2"));
    }
    SECTION("ten thousand random triangles finish within the bounds, every part drawn once") {
        std::vector<SortPolygon> polygons = sort_polygons(random_triangles({.count = 10000, .seed = 4, .size = 0.15, .far = 30}));
        const std::size_t visible = polygons.size();
        CHECK(visible > 9000);
        const Run r = run(std::move(polygons));
        CHECK_FALSE(r.result.bounded);
        CHECK(r.result.splits > 0);
        CHECK(r.result.order.size() == visible + r.result.splits);  // a split replaces one polygon by two
        std::vector<std::uint32_t> order = r.result.order;
        std::sort(order.begin(), order.end());
        CHECK(std::adjacent_find(order.begin(), order.end()) == order.end());
    }
}

TEST_CASE("translucent polygons composite back to front with over", "[depth-sort][transparency]") {
    const Scene s = load_scene(HSR_SOURCE_DIR "/assets/scenes/translucent_squares.toml");
    REQUIRE(s.polygons[0].opacity == 0.5);
    const Run r = run(sort_polygons(s));
    Image image(40, 40, {0, 0, 0});
    for (std::uint32_t i : r.result.order) {
        std::vector<glm::dvec4> ndc;
        for (const Vec3& v : r.result.polygons[i].vertices) ndc.emplace_back(v, 1.0);
        paint_clip_polygon(image, std::move(ndc), r.result.polygons[i].id, r.result.polygons[i].color, r.result.polygons[i].opacity);
    }
    const std::size_t k = 3 * std::size_t(20 * 40 + 20);  // the centre: red over blue
    CHECK(int(image.rgb[k]) == 128);
    CHECK(int(image.rgb[k + 1]) == 0);
    CHECK(int(image.rgb[k + 2]) == 128);
    CHECK(image.id(20, 20) == 1);  // the id image names the front polygon
    // In the scene's own order (front first), "over" would leave the blue square covering the red
    Image wrong(40, 40, {0, 0, 0});
    for (const auto& p : sort_polygons(s)) {
        std::vector<glm::dvec4> ndc;
        for (const Vec3& v : p.vertices) ndc.emplace_back(v, 1.0);
        paint_clip_polygon(wrong, std::move(ndc), p.id, p.color, p.opacity);
    }
    CHECK(int(wrong.rgb[k]) == 0);
    CHECK(int(wrong.rgb[k + 2]) == 255);
}

TEST_CASE("the depth-sort lessons' scenes do what their lessons say", "[depth-sort][lessons]") {
    SECTION("simple case: no z extents overlap, so no pair is examined") {
        const Scene s = lesson_scene("depth_sort_layers.toml");
        const Run r = run(sort_polygons(s));
        CHECK(r.result.pairs == 0);
        CHECK(r.result.order == std::vector<std::uint32_t>{1, 3, 2, 0});  // z = -1.5, -0.6, 0.3, 1.2: far to near
        const auto [compared, wrong, ties] = compare_with_ray_cast(s, r.result, {64, 48});
        CHECK(compared > 1000);
        CHECK(wrong == 0);
        CHECK(ties == 0);
    }
    SECTION("one pair for each test: tests 1 to 5 and the swapped test 3 each settle a pair") {
        const Run r = run(sort_polygons(lesson_scene("depth_sort_tests.toml")));
        std::vector<OrderTest> deciders;
        for (const auto& e : r.events)
            if (const auto* t = std::get_if<TestTried>(&e); t && t->passed) deciders.push_back(t->test);
        // the last pair is examined twice: once to move Q ahead, once with the roles swapped, when test 3 holds
        CHECK(deciders == std::vector<OrderTest>{OrderTest::x_extents, OrderTest::y_extents, OrderTest::r_behind_q,
                                                 OrderTest::q_in_front_of_r, OrderTest::projections,
                                                 OrderTest::q_behind_r, OrderTest::r_behind_q});
        CHECK(r.result.moves == 1);
        CHECK(r.result.splits == 0);
    }
    SECTION("piercing triangles: a split, then the ray cast's image") {
        const Scene s = lesson_scene("depth_sort_piercing.toml");
        const Run r = run(sort_polygons(s));
        CHECK(r.result.splits == 1);
        const auto [compared, wrong, ties] = compare_with_ray_cast(s, r.result, {64, 48});
        CHECK(compared > 1000);
        CHECK(wrong == 0);
        CHECK(ties == 0);
    }
    SECTION("translucent panes: red over green over blue where all three overlap") {
        const Scene s = lesson_scene("translucent_panes.toml");
        const Run r = run(sort_polygons(s));
        CHECK(r.result.pairs == 1);
        Image image(64, 48, {0, 0, 0});
        for (std::uint32_t i : r.result.order) {
            std::vector<glm::dvec4> ndc;
            for (const Vec3& v : r.result.polygons[i].vertices) ndc.emplace_back(v, 1.0);
            paint_clip_polygon(image, std::move(ndc), r.result.polygons[i].id, r.result.polygons[i].color, r.result.polygons[i].opacity);
        }
        // the screen centre is on all three: blue wall, then green (0.55), then red (0.55), each "over"
        const auto over = [](double front, double alpha, double back) { return alpha * front + (1 - alpha) * back; };
        const double red = over(0xff, 0.55, over(0x30, 0.55, 0x30));
        const double green = over(0x30, 0.55, over(0xd0, 0.55, 0x50));
        const double blue = over(0x30, 0.55, over(0x40, 0.55, 0xff));
        const std::size_t k = 3 * std::size_t(24 * 64 + 32);
        CHECK(std::abs(int(image.rgb[k]) - red) <= 1);
        CHECK(std::abs(int(image.rgb[k + 1]) - green) <= 1);
        CHECK(std::abs(int(image.rgb[k + 2]) - blue) <= 1);
        CHECK(image.id(32, 24) == 1);
    }
}

TEST_CASE("depth sort on 60 and 120 random piercing triangles paints what the ray cast sees, but for edge pixels", "[depth_sort][raycast][reference]") {
    // Found by `hsrviz report`: once polygons are moved to the head of the list, the head need not be the farthest,
    // and a polygon wholly behind it must still be tested (it was skipped as "z extents apart": 9% of pixels wrong).
    for (const std::size_t count : {60u, 120u})
        for (const std::uint32_t seed : {5u, 6u, 7u}) {
            INFO(count << " triangles, seed " << seed);
            const Scene s = random_triangles({.count = count, .seed = seed, .size = 2.5});
            const Viewport vp{256, 192};
            const auto painted = hsr::analysis::paint_depth_sort(s, vp);
            const RayCastResult ref = ray_cast(s, {.viewport = vp, .acceleration = Acceleration::grid, .detail = RayDetail::ray}).run_to_end();
            std::size_t differ = 0;
            for (std::size_t k = 0; k < ref.image.ids.size(); ++k) differ += painted.image.ids[k] != ref.image.ids[k];
            CHECK_FALSE(painted.sorted.bounded);
            CHECK(differ < 30);  // of 49,152: pixel centres on an edge, where the two rasterisations may differ
        }
}

TEST_CASE("depth sort ends on interpenetrating triangles whose moves go round a cycle no plane cuts", "[depth-sort][bounds]") {
    // the differential run's regression scene: it once moved polygons to the head of the list until 2^32 pairs
    const Scene scene = load_scene(HSR_SOURCE_DIR "/assets/scenes/extreme/depth_sort_interpenetrating.toml");
    const DepthSortResult r = depth_sort(sort_polygons(scene)).run_to_end();
    CHECK_FALSE(r.bounded);
    CHECK(r.pairs < 20'000);
    CHECK(r.order.size() == r.polygons.size() - r.splits);  // every part drawn once (a split replaces one by two)
    // a bound is reached in well-defined steps and says so
    const DepthSortResult bounded = depth_sort(sort_polygons(scene), {.max_pairs = 50}).run_to_end();
    CHECK(bounded.bounded);
    CHECK(bounded.pairs == 51);
}

TEST_CASE("front-to-back display: the nearest polygon fills the screen, the display stops, the rest are never drawn", "[depth_sort]") {
    // A square over the whole canonical volume's face, nearest; two smaller ones behind it
    std::vector<SortPolygon> p = {poly(1, {{-0.2, -0.2, 0.6}, {0.2, -0.2, 0.6}, {0.2, 0.2, 0.6}, {-0.2, 0.2, 0.6}}),
                                  poly(2, {{-1, -1, -0.5}, {1, -1, -0.5}, {1, 1, -0.5}, {-1, 1, -0.5}}),
                                  poly(3, {{0.1, 0.1, 0.3}, {0.5, 0.1, 0.3}, {0.5, 0.5, 0.3}, {0.1, 0.5, 0.3}})};
    const Run sorted = run(p);
    const Viewport vp{16, 12};
    std::vector<FrontToBackEvent> events;
    auto machine = display_front_to_back(sorted.result.polygons, sorted.result.order, vp);
    for (const auto& e : machine) events.push_back(e);
    const FrontToBackResult& r = machine.result();
    REQUIRE(events.size() == 2);
    const auto& first = std::get<FrontPolygonDrawn>(events[0]);
    CHECK(first.id == 2);
    CHECK(first.written == 16u * 12u);
    CHECK(first.unwritten == 0);
    CHECK(std::get<ScreenFilled>(events[1]) == ScreenFilled{1, 2});
    CHECK(r.drawn == 1);
    CHECK(r.left == 2);
    for (const SceneId id : r.image.ids) CHECK(id == 2);
    CHECK_THAT(describe(events[1]), Catch::Contains("stop"));
}

TEST_CASE("front-to-back display: a polygon is written only where no nearer one was, and the list runs out on a gap", "[depth_sort]") {
    // the near square covers the middle; the far one, larger, shows round it; the corners stay background
    std::vector<SortPolygon> p = {poly(1, {{-0.8, -0.8, 0.5}, {0.8, -0.8, 0.5}, {0.8, 0.8, 0.5}, {-0.8, 0.8, 0.5}}),
                                  poly(2, {{-0.4, -0.4, -0.5}, {0.4, -0.4, -0.5}, {0.4, 0.4, -0.5}, {-0.4, 0.4, -0.5}})};
    const Run sorted = run(p);
    const Viewport vp{20, 20};
    std::vector<FrontToBackEvent> events;
    auto machine = display_front_to_back(sorted.result.polygons, sorted.result.order, vp);
    for (const auto& e : machine) events.push_back(e);
    REQUIRE(events.size() == 3);
    const auto& near = std::get<FrontPolygonDrawn>(events[0]);
    const auto& far = std::get<FrontPolygonDrawn>(events[1]);
    CHECK(near.id == 2);
    CHECK(near.written == 8u * 8u);  // [-0.4, 0.4] of 20 pixels across 2 units: 8 × 8
    CHECK(near.hidden == 0);
    CHECK(far.id == 1);
    CHECK(far.written == 16u * 16u - 8u * 8u);
    CHECK(far.hidden == 8u * 8u);
    CHECK(std::get<FrontDisplayFinished>(events[2]) == FrontDisplayFinished{2, 20u * 20u - 16u * 16u});
}
