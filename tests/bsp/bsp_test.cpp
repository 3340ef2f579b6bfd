// SPDX-License-Identifier: MIT
// BSP build and traversal: painting in the traversal's order gives the nearest-hit ray cast's picture, in 2D and
// 3D; every polygon is drawn exactly once; the extreme cases of the issue.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <random>

#include <glm/matrix.hpp>

#include "bsp/bsp_tree.h"
#include "catch.h"
#include "raster/image.h"
#include "core/numeric.h"
#include "raycast/nearest_hit.h"

using namespace hsr::algo;

namespace {

struct Built {
    BspTree tree;
    std::vector<BspEvent> events;
};

Built build(std::vector<BspInput> in, BspOptions o = {}) {
    Built b;
    auto m = build_bsp(std::move(in), o);
    for (const auto& e : m) b.events.push_back(e);
    b.tree = m.result();
    return b;
}

std::vector<BspPolygonId> paint_order(const BspTree& t, Vec3 eye, Order order = Order::back_to_front) {
    return traverse_bsp(&t, eye, order).run_to_end();
}

std::vector<BspInput> random_triangles(std::mt19937_64& rng, int n, Vec3 offset = Vec3(0)) {
    std::uniform_real_distribution<double> x(-2, 2), z(-6, -2), r(-1.2, 1.2);
    std::vector<BspInput> out;
    for (int i = 0; i < n; ++i) {
        const Vec3 c(x(rng), x(rng), z(rng));
        out.push_back({i + 1, {c + Vec3(r(rng), r(rng), r(rng)) + offset, c + Vec3(r(rng), r(rng), r(rng)) + offset,
                               c + Vec3(r(rng), r(rng), r(rng)) + offset}});
    }
    return out;
}

// Which source id a ray sees: the last polygon of the painter's order it hits, or the nearest input it hits.
int painted(const BspTree& t, const std::vector<BspPolygonId>& order, const Ray& ray) {
    int id = 0;
    for (BspPolygonId p : order) {
        const BspPolygon& poly = t.polygons[std::size_t(p)];
        if (hit(ray, poly.vertices, poly.plane)) id = poly.source;
    }
    return id;
}
int ray_cast(const std::vector<BspInput>& in, const std::vector<Plane>& planes, const Ray& ray) {
    std::vector<std::vector<Vec3>> polys;
    for (const auto& p : in) polys.push_back(p.vertices);
    const auto h = nearest_hit(ray, polys, planes);
    return h ? in[h->index].id : 0;
}

struct Comparison {
    int compared = 0, boundary = 0, wrong = 0;
};

// Rays through pixel centres of a w×h image (3D, looking down −z with a 60° field of view), or w rays around the
// eye (2D). A sample whose neighbours half a pixel away see another id is on a boundary and is not compared.
Comparison compare_images(const std::vector<BspInput>& in, const BspTree& t, Vec3 eye, bool two_d, int w, int h) {
    std::vector<Plane> planes;
    for (const auto& p : in) {
        Plane pl;
        plane_of(p.vertices, pl);
        planes.push_back(pl);
    }
    const auto order = paint_order(t, eye);
    const auto ray_at = [&](double i, double j) {
        if (two_d) {
            const double a = 2 * 3.141592653589793 * i / w;
            return Ray{eye, Vec3(std::cos(a), std::sin(a), 0)};
        }
        const double s = std::tan(3.141592653589793 / 6);
        return Ray{eye, Vec3((2 * (i + 0.5) / w - 1) * s, (1 - 2 * (j + 0.5) / h) * s, -1)};
    };
    Comparison c;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const int want = ray_cast(in, planes, ray_at(i, j)), got = painted(t, order, ray_at(i, j));
            bool boundary = false;
            for (const auto& [di, dj] : {std::pair{-0.5, 0.0}, {0.5, 0.0}, {0.0, -0.5}, {0.0, 0.5}})
                boundary = boundary || ray_cast(in, planes, ray_at(i + di, j + dj)) != want;
            if (boundary) {
                ++c.boundary;
                continue;
            }
            ++c.compared;
            c.wrong += got != want;
        }
    return c;
}

// Each source polygon's drawn parts add up to its measure (area, or length in 2D), and no part is drawn twice.
void check_drawn_once(const std::vector<BspInput>& in, const BspTree& t, const std::vector<BspPolygonId>& order) {
    std::map<int, double> drawn;
    std::vector<int> times(t.polygons.size(), 0);
    for (BspPolygonId p : order) {
        ++times[std::size_t(p)];
        drawn[t.polygons[std::size_t(p)].source] += measure(t.polygons[std::size_t(p)].vertices);
    }
    for (int k : times) REQUIRE(k <= 1);
    REQUIRE(order.size() == in.size() + t.splits);  // each split turns one polygon into two
    for (const auto& p : in) {
        INFO("polygon " << p.id);
        CHECK(drawn[p.id] == Approx(measure(p.vertices)).epsilon(1e-9));
    }
}

}  // namespace

TEST_CASE("splitting a polygon by a plane keeps its area, on both sides", "[bsp][plane]") {
    const std::vector<Vec3> square = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    const Plane x_half{{1, 0, 0}, -0.5};  // x = 0.5
    const Tolerance tol{1e-9};
    CHECK(classify(x_half, square, tol) == PolygonSide::spanning);
    const SplitParts parts = split(x_half, square, tol);
    CHECK(measure(parts.front) == Approx(1.0));
    CHECK(measure(parts.back) == Approx(3.0));
    CHECK(classify(Plane{{0, 0, 1}, 0}, square, tol) == PolygonSide::coplanar);
    CHECK(classify(Plane{{1, 0, 0}, -1}, square, tol) == PolygonSide::back);  // touching x = 1 from behind
    // a 2D segment crossing the line x = 0.5
    const std::vector<Vec3> segment = {{0, 0, 0}, {2, 0, 0}};
    const SplitParts halves = split(x_half, segment, tol);
    CHECK(measure(halves.front) == Approx(1.5));
    CHECK(measure(halves.back) == Approx(0.5));
}

TEST_CASE("a polygon's plane at any magnitude: 1e-160 across, 1e150 across", "[bsp][plane]") {
    // issue 53, item 12: Newell's products of a triangle 1e-160 across are 1e-320, and their length underflowed to 0,
    // so the BSP alone refused the triangle every other algorithm drew
    for (const double k : {1e-160, 1e-300, 1.0, 1e150}) {
        const std::vector<Vec3> triangle = {Vec3(-2, -1, -1.5) * k, Vec3(1.6, -0.8, 0.8) * k, Vec3(-0.4, 1.6, -0.2) * k};
        Plane plane, unit;
        REQUIRE(plane_of(triangle, plane));
        REQUIRE(plane_of(std::vector<Vec3>{{-2, -1, -1.5}, {1.6, -0.8, 0.8}, {-0.4, 1.6, -0.2}}, unit));
        CHECK(glm::length(plane.n - unit.n) < 1e-12);
        for (const Vec3& v : triangle) CHECK(std::abs(plane.distance(v)) <= 1e-12 * 3 * k);
        const Built b = build({{1, triangle}});
        CHECK(b.tree.held() == 1);
    }
    Plane none;
    CHECK_FALSE(plane_of(std::vector<Vec3>{{0, 0, 0}, {1e-160, 0, 0}, {2e-160, 0, 0}}, none));  // on one line: still none
}

TEST_CASE("painting in BSP order gives the ray-cast picture in 3D, for every splitter rule", "[bsp][raycast]") {
    const SplitterRule rule =
        GENERATE(SplitterRule::first, SplitterRule::balanced, SplitterRule::fewest_splits, SplitterRule::weighted);
    std::mt19937_64 rng(1000 + int(rule));
    std::uniform_real_distribution<double> jitter(-0.5, 0.5);
    Comparison total;
    for (int scene = 0; scene < 6; ++scene) {
        const auto in = random_triangles(rng, 24);
        const Built b = build(in, {.splitter = rule});
        const Vec3 eye(jitter(rng), jitter(rng), jitter(rng));
        const Comparison c = compare_images(in, b.tree, eye, false, 48, 48);
        check_drawn_once(in, b.tree, paint_order(b.tree, eye));
        total.compared += c.compared, total.boundary += c.boundary, total.wrong += c.wrong;
    }
    std::cout << "BSP 3D (" << to_string(rule) << "): " << total.compared << " pixels compared, " << total.wrong
              << " wrong, " << total.boundary << " on boundaries\n";
    CHECK(total.compared > 6 * 48 * 48 / 2);
    CHECK(total.wrong == 0);
}

TEST_CASE("painting in BSP order gives the ray-cast picture in 2D", "[bsp][raycast]") {
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> xy(-5, 5), r(-2, 2);
    for (int scene = 0; scene < 10; ++scene) {
        std::vector<BspInput> in;
        for (int i = 0; i < 30; ++i) {
            const Vec3 c(xy(rng), xy(rng), 0);
            in.push_back({i + 1, {c + Vec3(r(rng), r(rng), 0), c + Vec3(r(rng), r(rng), 0)}});
        }
        const Built b = build(in, {.splitter = SplitterRule::balanced});
        const Vec3 eye(xy(rng), xy(rng), 0);
        const Comparison c = compare_images(in, b.tree, eye, true, 1440, 1);
        check_drawn_once(in, b.tree, paint_order(b.tree, eye));
        CHECK(c.wrong == 0);
        CHECK(c.compared > 1000);
    }
}

TEST_CASE("front-to-back order is the back-to-front order reversed", "[bsp]") {
    std::mt19937_64 rng(5);
    const auto in = random_triangles(rng, 30);
    const Built b = build(in);
    auto btf = paint_order(b.tree, Vec3(0.1, 0.2, 0.3));
    const auto ftb = paint_order(b.tree, Vec3(0.1, 0.2, 0.3), Order::front_to_back);
    std::reverse(btf.begin(), btf.end());
    CHECK(btf == ftb);
}

TEST_CASE("point location follows the planes from the root to a leaf", "[bsp][locate]") {
    std::mt19937_64 rng(9);
    const auto in = random_triangles(rng, 40);
    const Built b = build(in, {.splitter = SplitterRule::balanced});
    std::uniform_real_distribution<double> u(-4, 4);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p(u(rng), u(rng), u(rng) - 4);
        const Location where = locate(b.tree, p);
        REQUIRE(!where.path.empty());
        CHECK(where.path.front() == b.tree.root);
        CHECK(where.path.size() <= b.tree.depth);
        for (std::size_t k = 0; k < where.path.size(); ++k) {
            const BspNode& n = b.tree.nodes[std::size_t(where.path[k])];
            CHECK(where.sides[k] == classify(n.plane, p, node_tolerance(b.tree, n, p)));
            if (k + 1 < where.path.size())
                CHECK(where.path[k + 1] == (where.sides[k] == Side::back ? n.back : n.front));
        }
    }
}

TEST_CASE("the build's events agree with the tree it returns", "[bsp][events]") {
    std::mt19937_64 rng(12);
    const Built b = build(random_triangles(rng, 40), {.splitter = SplitterRule::weighted});
    std::size_t splits = 0, chosen = 0;
    for (const auto& e : b.events) {
        if (const auto* s = std::get_if<PolygonSplit>(&e)) {
            ++splits;
            CHECK(*s->front == b.tree.polygons[std::size_t(s->front_part)].vertices);
            CHECK(*s->back == b.tree.polygons[std::size_t(s->back_part)].vertices);
            CHECK(b.tree.polygons[std::size_t(s->front_part)].label ==
                  b.tree.polygons[std::size_t(s->polygon)].label + "f");
        }
        if (const auto* c = std::get_if<SplitterChosen>(&e)) {
            ++chosen;
            CHECK(b.tree.nodes[std::size_t(c->node)].plane == c->plane);
            CHECK(c->candidates >= 1);
        }
    }
    CHECK(splits == b.tree.splits);
    CHECK(chosen == b.tree.nodes.size());
    const auto* done = std::get_if<BuildFinished>(&b.events.back());
    REQUIRE(done);
    CHECK(done->nodes == b.tree.nodes.size());
    CHECK(done->splits == b.tree.splits);
    const auto labels = b.tree.labels();
    const PolygonNamer name = [&](BspPolygonId p) { return labels.at(std::size_t(p)); };
    for (const auto& e : b.events) CHECK_FALSE(describe(e, name).empty());
}

TEST_CASE("BSP extreme cases", "[bsp][extreme]") {
    const auto quad = [](int id, double z, double dz = 0) {
        return BspInput{id, {{-1, -1, z}, {1, -1, z}, {1, 1, z + dz}, {-1, 1, z}}};
    };
    SECTION("polygons coplanar with the splitter stay at its node, unsplit") {
        const Built b = build({quad(1, -3), {2, {{0.5, 0.5, -3}, {3, 0.5, -3}, {0.5, 3, -3}}}, quad(3, -5)});
        CHECK(b.tree.splits == 0);
        CHECK(b.tree.nodes[0].polygons.size() == 2);
    }
    SECTION("a quad slightly non-planar, and a polygon within the tolerance of a plane, are not split") {
        const Built b = build({quad(1, -3, 1e-12), {2, {{-3, 0, -3 + 1e-12}, {3, 0, -3 - 1e-12}, {0, 3, -3}}}});
        CHECK(b.tree.splits == 0);
        CHECK(b.tree.nodes[0].polygons.size() == 2);
    }
    SECTION("a scene around 1e6 splits exactly as the same scene at the origin (the tolerance scales)") {
        std::mt19937_64 a(31), c(31);
        const Built here = build(random_triangles(a, 30), {.splitter = SplitterRule::balanced});
        const Built far = build(random_triangles(c, 30, Vec3(1e6, -1e6, 1e6)), {.splitter = SplitterRule::balanced});
        CHECK(far.tree.splits == here.tree.splits);
        CHECK(far.tree.nodes.size() == here.tree.nodes.size());
    }
    SECTION("every polygon crossing one plane: the first rule splits them all, fewest-splits none") {
        // A small square in the plane z = −5, off to the right; 20 parallel triangles (planes x = c) each crossing
        // z = −5. With the square first, the first rule splits all 20; any triangle as splitter splits nothing.
        std::vector<BspInput> in = {{1, {{10, -1, -5}, {12, -1, -5}, {12, 1, -5}, {10, 1, -5}}}};
        for (int i = 0; i < 20; ++i) {
            const double x = -5 + 0.5 * i;
            in.push_back({i + 2, {{x, -1, -4}, {x, 1, -4}, {x, 0, -6}}});
        }
        const Built first = build(in, {.splitter = SplitterRule::first});
        CHECK(first.tree.splits == 20);
        const Built fewest = build(in, {.splitter = SplitterRule::fewest_splits});
        CHECK(fewest.tree.splits == 0);
        check_drawn_once(in, first.tree, paint_order(first.tree, Vec3(0.2, 0, 0)));
        check_drawn_once(in, fewest.tree, paint_order(fewest.tree, Vec3(0.2, 0, 0)));
    }
    SECTION("duplicated polygons are both kept and both drawn") {
        const Built b = build({quad(1, -3), quad(2, -3)});
        CHECK(b.tree.nodes.size() == 1);
        CHECK(paint_order(b.tree, Vec3(0)).size() == 2);
    }
    SECTION("degenerate, NaN and too-small input is refused with the polygon named") {
        CHECK_THROWS_WITH(build_bsp({{7, {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}}}), "polygon 7 is degenerate (it has no area)");
        CHECK_THROWS_WITH(build_bsp({{8, {{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}}}}), "polygon 8 vertex 2.y is NaN");
        CHECK_THROWS_WITH(build_bsp({{9, {{0, 0, 0}}}}), "polygon 9 has fewer than 2 vertices");
    }
    SECTION("a depth bound ends the build with an event, and every polygon is still drawn once") {
        std::mt19937_64 rng(4);
        const auto in = random_triangles(rng, 30);
        const Built b = build(in, {.max_depth = 3});
        CHECK(b.tree.bounded);
        CHECK(std::any_of(b.events.begin(), b.events.end(),
                          [](const BspEvent& e) { return std::holds_alternative<BspBoundReached>(e); }));
        check_drawn_once(in, b.tree, paint_order(b.tree, Vec3(0)));
    }
    SECTION("a classification bound ends the build with an event naming it, and every polygon is still drawn once") {
        std::mt19937_64 rng(4);
        const auto in = random_triangles(rng, 30);
        const Built whole = build(in);
        REQUIRE(whole.tree.classifications > 40);
        const Built b = build(in, {.max_classifications = 40});
        CHECK(b.tree.bounded);
        CHECK(b.tree.classifications > 40);  // the one that found the bound is counted, then nothing more is classified
        const auto classified = std::count_if(b.events.begin(), b.events.end(), [](const BspEvent& e) {
            return std::holds_alternative<PolygonClassified>(e);
        });
        CHECK(classified == 40);
        CHECK(std::any_of(b.events.begin(), b.events.end(), [](const BspEvent& e) {
            const auto* bound = std::get_if<BspBoundReached>(&e);
            return bound && bound->bound == BspBound::classifications && bound->limit == 40;
        }));
        check_drawn_once(in, b.tree, paint_order(b.tree, Vec3(0)));
    }
    SECTION("the default classification bound lets an ordinary build finish") {
        std::mt19937_64 rng(5);
        const Built b = build(random_triangles(rng, 200));
        CHECK_FALSE(b.tree.bounded);
        CHECK(b.tree.classifications < (1u << 24));
    }
    SECTION("an eye on a splitting plane still gets a correct order") {
        std::mt19937_64 rng(8);
        const auto in = random_triangles(rng, 20);
        const Built b = build(in);
        const BspPolygon& root = b.tree.polygons[std::size_t(b.tree.nodes[0].polygons[0])];
        const Vec3 on_plane = root.vertices[0] + Vec3(0, 0, 4) - root.plane.n * root.plane.distance(root.vertices[0] + Vec3(0, 0, 4));
        REQUIRE(classify(root.plane, on_plane, node_tolerance(b.tree, b.tree.nodes[0], on_plane)) == Side::on);
        CHECK(compare_images(in, b.tree, on_plane, false, 32, 32).wrong == 0);
    }
}

TEST_CASE("the painter's fill in BSP order gives the ray cast's id image through the same pixel centres",
          "[bsp][raster]") {
    std::mt19937_64 rng(21);
    Camera camera;
    camera.eye = Vec3(0.3, 0.2, 0.5);
    camera.target = Vec3(0, 0, -4);
    camera.near = 0.1;
    camera.far = 50;
    const int w = 64, h = 48;
    camera.aspect = double(w) / h;
    const glm::dmat4 vp_wide = view_projection(camera), inverse_wide = glm::inverse(vp_wide);
    int compared = 0, wrong = 0;
    for (int scene = 0; scene < 4; ++scene) {
        const auto in = random_triangles(rng, 25);
        const Built b = build(in, {.splitter = SplitterRule::balanced});
        Image image(w, h);
        for (BspPolygonId p : paint_order(b.tree, camera.eye)) {
            const BspPolygon& poly = b.tree.polygons[std::size_t(p)];
            paint_polygon(image, vp_wide, poly.vertices, poly.source, {255, 255, 255});
        }
        std::vector<std::vector<Vec3>> polys;
        std::vector<Plane> planes;
        for (const auto& p : in) {
            polys.push_back(p.vertices);
            planes.emplace_back();
            plane_of(p.vertices, planes.back());
        }
        const auto seen = [&](double px, double py) {  // the ray through a point of the image (pixel units)
            const glm::dvec4 ndc((px / w) * 2 - 1, 1 - (py / h) * 2, -1, 1);
            const glm::dvec4 a = inverse_wide * ndc, z = inverse_wide * glm::dvec4(ndc.x, ndc.y, 1, 1);
            const Vec3 from = Vec3(a) / a.w, to = Vec3(z) / z.w;
            const auto hit = nearest_hit({camera.eye, to - from}, polys, planes);
            return hit ? in[hit->index].id : 0;
        };
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const int want = seen(x + 0.5, y + 0.5);
                if (seen(x, y + 0.5) != want || seen(x + 1, y + 0.5) != want || seen(x + 0.5, y) != want ||
                    seen(x + 0.5, y + 1) != want)
                    continue;  // a boundary pixel
                constexpr double snap = 0.01;  // the fill snaps vertices to 1/256 pixel: centres this near an edge may go either way
                if (seen(x + 0.5 - snap, y + 0.5) != want || seen(x + 0.5 + snap, y + 0.5) != want ||
                    seen(x + 0.5, y + 0.5 - snap) != want || seen(x + 0.5, y + 0.5 + snap) != want)
                    continue;
                ++compared;
                wrong += image.id(x, y) != want;
            }
    }
    CHECK(compared > 4 * w * h / 2);
    CHECK(wrong == 0);
}

TEST_CASE("the count of polygons in the tree is what a traversal draws: one more for each split", "[bsp]") {
    std::mt19937_64 rng(17);
    for (int round = 0; round < 20; ++round) {
        const auto in = random_triangles(rng, 12);
        const BspTree tree = build_bsp(in, {}).run_to_end();
        const auto order = traverse_bsp(&tree, Vec3(0, 0, 30)).run_to_end();
        CHECK(tree.held() == order.size());
        CHECK(tree.held() == in.size() + tree.splits);
        if (tree.splits > 0) CHECK(tree.polygons.size() > tree.held());  // the split ones stay in the list
    }
}
