// SPDX-License-Identifier: MIT
// The geometry kernel (algorithms/geometry/): the cross product and turn, the shoelace area in its two forms, the
// convex hull, the half-space cut of a polygon and union–find and the slab test of a ray's interval, each with its degenerate inputs (fewer than 3
// points, no area, a cut through a vertex, a polygon wholly on one side).
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "catch.h"
#include "geometry/exact_collinear.h"
#include "geometry/half_space_cut.h"
#include "geometry/interval.h"
#include "geometry/polygon_2d.h"
#include "geometry/union_find.h"

using namespace hsr::algo;
using P = glm::dvec2;

namespace {
const std::vector<P> unit_square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // counter-clockwise
}  // namespace

TEST_CASE("The 2D cross product and the turn of three points have the sign of the turn", "[geometry]") {
    CHECK(cross({1, 0}, {0, 1}) == 1);
    CHECK(cross({0, 1}, {1, 0}) == -1);
    CHECK(cross({2, 3}, {4, 6}) == 0);  // parallel
    CHECK(orientation({0, 0}, {1, 0}, {1, 1}) > 0);   // left turn
    CHECK(orientation({0, 0}, {1, 0}, {1, -1}) < 0);  // right turn
    CHECK(orientation({0, 0}, {1, 1}, {3, 3}) == 0);  // in a line
    CHECK(orientation({5, 5}, {7, 5}, {5, 8}) == 6);  // twice the triangle's area
}

TEST_CASE("The shoelace area is signed by the winding and zero without area", "[geometry]") {
    SECTION("a square either way round") {
        CHECK(twice_signed_area(unit_square) == 2);
        CHECK(signed_area(unit_square) == 1);
        const std::vector<P> clockwise(unit_square.rbegin(), unit_square.rend());
        CHECK(signed_area(clockwise) == -1);
        CHECK(area(clockwise) == 1);
    }
    SECTION("fewer than 3 points") {
        CHECK(twice_signed_area(std::vector<P>{}) == 0);
        CHECK(twice_signed_area(std::vector<P>{{1, 2}}) == 0);
        CHECK(twice_signed_area(std::vector<P>{{1, 2}, {3, 5}}) == 0);
        CHECK(area_about_first_vertex({{1, 2}, {3, 5}}) == 0);
    }
    SECTION("points in a line, and a figure eight whose halves cancel") {
        CHECK(area(std::vector<P>{{0, 0}, {1, 1}, {2, 2}, {3, 3}}) == 0);
        CHECK(area(std::vector<P>{{0, 0}, {1, 1}, {1, 0}, {0, 1}}) == 0);
    }
    SECTION("a 3D polygon's shadow on z = 0, and integer sub-pixel vertices") {
        const std::vector<glm::dvec3> tilted{{0, 0, 5}, {2, 0, -1}, {2, 3, 7}};
        CHECK(signed_area(tilted) == 3);
        struct Pixel { std::int64_t x, y; };
        const std::vector<Pixel> pixels{{0, 0}, {256, 0}, {256, 256}};
        CHECK(twice_signed_area(pixels) == std::int64_t{256 * 256});
    }
    SECTION("far from the origin, about the first vertex keeps a sliver the origin form loses") {
        const double x = 1e5, w = 1e-9;  // products about the origin are ~1e10, their rounding ~1e-6 ≫ w
        const std::vector<P> sliver{{x, x}, {x + 1, x}, {x + 1, x + w}, {x, x + w}};
        CHECK(area_about_first_vertex(sliver) == Approx(w).epsilon(0.05));  // w itself is rounded at 1e5
        CHECK(area_about_first_vertex(unit_square) == 1);
    }
}

TEST_CASE("The convex hull is counter-clockwise without inner, repeated or collinear points", "[geometry]") {
    const std::vector<P> hull = convex_hull({{0, 0}, {2, 0}, {1, 0}, {2, 2}, {1, 1}, {0, 2}, {2, 2}, {0, 1}});
    CHECK(hull == std::vector<P>{{0, 0}, {2, 0}, {2, 2}, {0, 2}});
    CHECK(signed_area(hull) == 4);
    CHECK(convex_hull({}).empty());
    CHECK(convex_hull({{1, 1}, {1, 1}}).size() == 1);
    CHECK(convex_hull({{0, 0}, {1, 1}, {2, 2}}).size() < 3);  // in a line: no area
}

TEST_CASE("A half-space cut keeps the side where the value is not negative", "[geometry]") {
    const auto right_of_half = [](P p) { return p.x - 0.5; };
    SECTION("across the middle: two crossings") {
        const std::vector<P> kept = cut_polygon(unit_square, right_of_half);
        CHECK(kept == std::vector<P>{{0.5, 0}, {1, 0}, {1, 1}, {0.5, 1}});
        CHECK(signed_area(kept) == 0.5);
    }
    SECTION("a polygon wholly on one side") {
        CHECK(cut_polygon(unit_square, [](P p) { return p.x + 1; }) == unit_square);
        CHECK(cut_polygon(unit_square, [](P p) { return -1 - p.x; }).empty());
    }
    SECTION("a polygon touching the boundary from outside leaves only its edge on it") {
        CHECK(cut_polygon(unit_square, [](P p) { return -p.x; }) == std::vector<P>{{0, 0}, {0, 1}});
    }
    SECTION("fewer than 3 points") {
        CHECK(cut_polygon(std::vector<P>{}, right_of_half).empty());
        CHECK(cut_polygon(std::vector<P>{{1, 1}}, right_of_half) == std::vector<P>{{1, 1}});
        // a segment is a polygon of two edges there and back: each crossing is made once per way
        CHECK(cut_polygon(std::vector<P>{{0, 0}, {1, 0}}, right_of_half) == std::vector<P>{{0.5, 0}, {1, 0}, {0.5, 0}});
    }
    SECTION("a cut through a vertex: strict keeps it once, sign_change adds it again") {
        const std::vector<P> diamond{{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
        const auto right = [](P p) { return p.x; };
        CHECK(cut_polygon(diamond, right) == std::vector<P>{{0, -1}, {1, 0}, {0, 1}});
        CHECK(cut_polygon(diamond, right, {.crossing = Crossing::sign_change}) ==
              std::vector<P>{{0, -1}, {1, 0}, {0, 1}, {0, 1}, {0, -1}});
    }
    SECTION("the cap: crossings made and vertices on the boundary, in order") {
        std::vector<P> cap;
        cut_polygon(unit_square, right_of_half, {.on_boundary = &cap});
        CHECK(cap == std::vector<P>{{0.5, 0}, {0.5, 1}});
        cap.clear();
        const std::vector<P> diamond{{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
        cut_polygon(diamond, [](P p) { return p.x; }, {.on_boundary = &cap});
        CHECK(cap == std::vector<P>{{0, -1}, {0, 1}});
    }
    SECTION("a 3D polygon by a plane") {
        const std::vector<glm::dvec3> tri{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
        const auto at_most_y_1 = [](glm::dvec3 p) { return 1 - p.y; };
        const std::vector<glm::dvec3> kept = cut_polygon(tri, at_most_y_1);
        CHECK(kept == std::vector<glm::dvec3>{{0, 0, 0}, {4, 0, 0}, {3, 1, 0}, {0, 1, 0}});
    }
}

TEST_CASE("Union–find puts joined items in one group and leaves the rest apart", "[geometry]") {
    UnionFind groups(6);
    for (std::size_t i = 0; i < 6; ++i) CHECK(groups.find(i) == i);
    groups.join(0, 1);
    groups.join(2, 3);
    groups.join(1, 3);
    groups.join(4, 4);  // with itself: nothing changes
    CHECK(groups.find(0) == groups.find(2));
    CHECK(groups.find(1) == groups.find(3));
    CHECK(groups.find(0) != groups.find(4));
    CHECK(groups.find(4) == 4);
    CHECK(groups.find(5) == 5);
    CHECK(groups.find(0) == groups.find(3));  // join(a, b) puts a's group into b's: 3's root is the root of all
}

TEST_CASE("The slab test narrows a ray's interval and empties it when the ray misses", "[geometry]") {
    Interval t{0, 100};
    CHECK(narrow_to_slab(t, 2, 4, 0, 1));  // o = 0, d = 1: inside for t in [2, 4]
    CHECK((t.enter == 2 && t.exit == 4));
    CHECK(narrow_to_slab(t, -6, -3, 0, -2));  // going backwards: [1.5, 3], the ends swapped
    CHECK((t.enter == 2 && t.exit == 3));
    Interval parallel{0, 10};
    CHECK(narrow_to_slab(parallel, 0, 1, 0.5, 0));  // parallel and inside: unchanged
    CHECK((parallel.enter == 0 && parallel.exit == 10));
    CHECK_FALSE(narrow_to_slab(parallel, 0, 1, 2, 0));  // parallel and outside
    Interval touching{0, 10};
    CHECK(narrow_to_slab(touching, 10, 20, 0, 1));  // meets the slab at its exit: one point left
    CHECK((touching.enter == 10 && touching.exit == 10));
    CHECK_FALSE(narrow_to_slab(touching, 11, 20, 0, 1));
}

TEST_CASE("collinearity is decided exactly: no tolerance, no rounding", "[geometry]") {
    using V = glm::dvec3;
    const double third = 1.0 / 3;  // rounded: 3 × third is 1 in doubles, but not exactly
    CHECK_FALSE(collinear_exactly(std::vector<V>{{0, 0, 0}, {1, third, 0}, {3, 1, 0}}));
    CHECK(1.0 * 1 - third * 3 == 0.0);  // the same determinant in doubles says "collinear": why exactness is needed
    CHECK(collinear_exactly(std::vector<V>{{0, 0, 0}, {1, third, 0}, {2, 2 * third, 0}}));  // 2·third is exact
    CHECK(collinear_exactly(std::vector<V>{{5, 5, 5}, {5, 5, 5}, {5, 5, 5}}));              // one point
    CHECK(collinear_exactly(std::vector<V>{{1, 1, 1}, {1, 1, 1}, {2, 3, 4}}));              // a welded vertex
    CHECK_FALSE(collinear_exactly(std::vector<V>{{0, 0, 0}, {1, 0, 0}, {0.5, 1e-300, 0}}));  // a sliver
    CHECK_FALSE(collinear_exactly(std::vector<V>{{1e100, 0, 0}, {-1e100, 0, 0}, {0, 1e-100, 1e-100}}));
    // tiny and huge alike (scaled by a power of two, which is exact): multiples of one direction by powers of two
    for (const double s : {1e-200, 1.0, 1e200}) {
        const V d(s * third, s * 0.7, -s);
        CHECK(collinear_exactly(std::vector<V>{d, d * 2.0, d * -4.0, d * 0.5}));
        CHECK_FALSE(collinear_exactly(std::vector<V>{d, d * 2.0, V(d.x * 4, std::nextafter(d.y * 4, 0.0), d.z * 4)}));
    }
}
