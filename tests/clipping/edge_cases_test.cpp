// SPDX-License-Identifier: MIT
// The cases that break naive clippers: every outcode region, points on planes, edges and corners, near-parallel
// segments, huge and tiny coordinates, zero-length segments, w = 0, segments behind the eye and crossing w = 0,
// and NaN or infinite input.
#include <algorithm>
#include <cmath>
#include <limits>

#include "catch.h"
#include "clipping/clip_test_helpers.h"
#include "clipping/cohen_sutherland.h"
#include "analysis/exact_clip.h"
#include "clipping/liang_barsky.h"
#include "clipping/point_clip.h"
#include "clipping/sutherland_hodgman.h"
#include "core/numeric.h"

using namespace hsr::algo;
using hsr::test::drain;
using hsr::test::narrate;

namespace {

Vec4 pt(double x, double y, double z, double w = 1) { return {x, y, z, w}; }

SegmentClip cs(Vec4 a, Vec4 b, ClipSpace s) { return cohen_sutherland({1, a, b}, {.space = s}).run_to_end(); }
SegmentClip lb(Vec4 a, Vec4 b, ClipSpace s) { return liang_barsky({1, a, b}, {.space = s}).run_to_end(); }

bool close(const Vec4& a, const Vec4& b, double tol = 1e-12) {
    for (int i = 0; i < 4; ++i)
        if (std::fabs(a[i] - b[i]) > tol * std::max(1.0, std::fabs(b[i]))) return false;
    return true;
}

}  // namespace

TEST_CASE("the outcode of each of the 27 regions has the lecture's bits", "[clipping][outcode]") {
    for (int ix = -1; ix <= 1; ++ix)
        for (int iy = -1; iy <= 1; ++iy)
            for (int iz = -1; iz <= 1; ++iz) {
                const Vec4 p = pt(2.0 * ix, 2.0 * iy, 2.0 * iz);
                // bit 1: z > zmax, bit 2: z < zmin, bit 3: y > ymax, bit 4: y < ymin, bit 5: x > xmax, bit 6: x < xmin
                std::string expected = std::string(iz > 0 ? "1" : "0") + (iz < 0 ? "1" : "0") + (iy > 0 ? "1" : "0") +
                                       (iy < 0 ? "1" : "0") + (ix > 0 ? "1" : "0") + (ix < 0 ? "1" : "0");
                CHECK(to_string(outcode(p, ClipSpace::cube)) == expected);
                CHECK(to_string(outcode(p * 3.0, ClipSpace::homogeneous)) == expected);  // scaling by w = 3
            }
}

TEST_CASE("points on a plane, an edge or a corner are inside (the volume is closed)", "[clipping][outcode]") {
    for (const Vec4& p : {pt(1, 0, 0), pt(-1, 1, 0), pt(1, 1, 1), pt(-1, -1, -1)}) {
        CHECK(outcode(p, ClipSpace::cube).inside());
        CHECK(clip_point({1, p}, {.space = ClipSpace::cube}).run_to_end());
        CHECK(clip_point({1, p * 2.0}, {.space = ClipSpace::homogeneous}).run_to_end());
    }
    CHECK_FALSE(clip_point({1, pt(1 + 1e-15, 0, 0)}, {.space = ClipSpace::cube}).run_to_end());
}

TEST_CASE("segments with ends on planes, edges and corners", "[clipping][edge]") {
    const ClipSpace s = ClipSpace::cube;
    SECTION("a segment lying in a plane of the cube is accepted whole") {
        for (auto clip : {cs, lb}) {
            const SegmentClip c = clip(pt(1, -0.5, -0.5), pt(1, 0.5, 0.5), s);
            CHECK(c.outcome == ClipOutcome::inside);
        }
    }
    SECTION("a segment along an edge of the cube, longer than it, is cut to the edge") {
        for (auto clip : {cs, lb}) {
            const SegmentClip c = clip(pt(1, 1, -3), pt(1, 1, 3), s);
            REQUIRE(c.outcome == ClipOutcome::clipped);
            CHECK(close(c.a, pt(1, 1, -1)));
            CHECK(close(c.b, pt(1, 1, 1)));
        }
    }
    SECTION("a segment touching a corner from outside keeps only the corner") {
        for (auto clip : {cs, lb}) {
            const SegmentClip c = clip(pt(1, 1, 1), pt(3, 3, 3), s);
            REQUIRE(c.outcome == ClipOutcome::clipped);
            CHECK(close(c.a, pt(1, 1, 1)));
            CHECK(close(c.b, pt(1, 1, 1)));
        }
    }
    SECTION("a segment through two opposite corners is the cube's diagonal") {
        for (auto clip : {cs, lb}) {
            const SegmentClip c = clip(pt(-2, -2, -2), pt(2, 2, 2), s);
            REQUIRE(c.outcome == ClipOutcome::clipped);
            CHECK(close(c.a, pt(-1, -1, -1)));
            CHECK(close(c.b, pt(1, 1, 1)));
        }
    }
}

TEST_CASE("a segment nearly parallel to a plane (direction 1e-12) clips without blowing up", "[clipping][edge]") {
    // Just inside x = 1, drifting out of it by 1e-12 over its length: where it crosses x = 1 moves by 6e-4 for a
    // change of one ulp in x. Liang–Barsky computes every t from the original endpoints and is accurate to the
    // last bits; Cohen–Sutherland re-clips the already shortened (rounded) segment, so its error is the rounding
    // of the first cut amplified by 1 / |Δx|: a few ulp / 1e-12. That is the bound it is held to, and the lesson.
    const ClipSpace s = ClipSpace::cube;
    const Vec4 p1 = pt(1 - 0.5e-12, -3, 0), p2 = pt(1 + 0.5e-12, 3, 0);
    const auto exact = hsr::analysis::exact_clip_segment(p1, p2, s);
    REQUIRE(exact.visible);
    const double dx = p2.x - p1.x, eps = std::numeric_limits<double>::epsilon();

    const SegmentClip l = lb(p1, p2, s);
    REQUIRE(l.outcome == ClipOutcome::clipped);
    CHECK(hsr::analysis::relative_error(l.a, exact.a, 3) < 1e-15);
    CHECK(hsr::analysis::relative_error(l.b, exact.b, 3) < 1e-15);

    const SegmentClip c = cs(p1, p2, s);
    REQUIRE(c.outcome == ClipOutcome::clipped);
    CHECK(c.b.x == 1);  // snapped onto the plane it was cut at
    CHECK(outcode(c.a, s).inside());
    CHECK(outcode(c.b, s).inside());
    CHECK(hsr::analysis::relative_error(c.a, exact.a, 3) < 8 * eps / dx);
    CHECK(hsr::analysis::relative_error(c.b, exact.b, 3) < 8 * eps / dx);
}

TEST_CASE("coordinates near 1e30 and 1e-30 clip to the right part", "[clipping][edge]") {
    const ClipSpace s = ClipSpace::homogeneous;
    for (auto clip : {cs, lb}) {
        const SegmentClip big = clip(pt(-1e30, 0, 0, 1), pt(1e30, 0, 0, 1), s);
        REQUIRE(big.outcome == ClipOutcome::clipped);
        CHECK(close(big.a, pt(-1, 0, 0, 1), 1e-12));
        CHECK(close(big.b, pt(1, 0, 0, 1), 1e-12));
        const SegmentClip tiny = clip(pt(1e-30, -1e-30, 0, 1), pt(-1e-30, 1e-30, 0, 1), s);
        CHECK(tiny.outcome == ClipOutcome::inside);
        const SegmentClip scaled = clip(pt(-3e30, 0, 0, 1e30), pt(3e30, 0, 0, 1e30), s);
        REQUIRE(scaled.outcome == ClipOutcome::clipped);
        CHECK(close(scaled.a, pt(-1e30, 0, 0, 1e30)));
    }
}

TEST_CASE("a zero-length segment is a point: kept inside, dropped outside", "[clipping][edge]") {
    for (auto clip : {cs, lb}) {
        CHECK(clip(pt(0.5, 0.5, 0.5), pt(0.5, 0.5, 0.5), ClipSpace::cube).outcome == ClipOutcome::inside);
        CHECK(clip(pt(2, 0, 0), pt(2, 0, 0), ClipSpace::cube).outcome == ClipOutcome::rejected);
    }
}

TEST_CASE("points behind the eye and at w = 0 are outside the homogeneous volume", "[clipping][w]") {
    const ClipSpace h = ClipSpace::homogeneous;
    CHECK(outcode(pt(0, 0, 0, 0), h).has(ClipPlane::w_min));
    CHECK_FALSE(clip_point({1, pt(0, 0, 0, 0)}, {.space = h}).run_to_end());
    // (2, 2, 2, -2) divides to (-1, -1, -1), a corner of the cube: it must not be kept
    CHECK_FALSE(clip_point({1, pt(2, 2, 2, -2)}, {.space = h}).run_to_end());
    SECTION("both endpoints behind the eye: rejected") {
        for (auto clip : {cs, lb}) CHECK(clip(pt(0, 0, 1, -1), pt(0.5, 0, 2, -3), h).outcome == ClipOutcome::rejected);
    }
    SECTION("an endpoint at w = 0 is cut back to w ≥ ε") {
        for (auto clip : {cs, lb}) {
            const SegmentClip c = clip(pt(0, 0, 0, 0), pt(0, 0, 0, 2), h);
            REQUIRE(c.outcome == ClipOutcome::clipped);
            CHECK(c.a.w == ClipTolerance::w_epsilon);  // snapped onto the plane exactly
            CHECK(c.b == pt(0, 0, 0, 2));
        }
    }
}

TEST_CASE("a segment from w = −3 to w = 2 comes out as its visible part, never the external segment", "[clipping][w]") {
    const ClipSpace h = ClipSpace::homogeneous;
    // p1 divides to (−1/3, 0, 1/3): inside the cube after the divide, but it is behind the eye. Dividing first
    // would keep the "external" segment through infinity; clipping first keeps only the part with w > 0.
    const Vec4 p1 = pt(1, 0, -1, -3), p2 = pt(0.5, 0, 0, 2);
    const auto exact = hsr::analysis::exact_clip_segment(p1, p2, h);
    REQUIRE(exact.visible);
    for (auto clip : {cs, lb}) {
        const SegmentClip c = clip(p1, p2, h);
        INFO(narrate(drain(cohen_sutherland({1, p1, p2}, {.space = h})).events, h));
        REQUIRE(c.outcome == ClipOutcome::clipped);
        CHECK(c.a.w > 0);
        CHECK(c.b.w > 0);
        CHECK(hsr::analysis::relative_error(c.a, exact.a, 3) < 1e-15);
        CHECK(hsr::analysis::relative_error(c.b, exact.b, 3) < 1e-15);
        for (const Vec4& v : {c.a, c.b}) CHECK(outcode(v, h).inside());
    }
    const PolygonClip poly = sutherland_hodgman({1, {p1, p2, pt(0.5, 0.5, 0, 2)}}, {.space = h}).run_to_end();
    for (const Vec4& v : poly.vertices) CHECK(v.w > 0);
}

TEST_CASE("Cohen–Sutherland takes at most one round per plane and never spins", "[clipping][bound]") {
    std::mt19937_64 rng(7);
    for (const ClipSpace s : {ClipSpace::cube, ClipSpace::homogeneous}) {
        std::size_t most = 0;
        for (int n = 0; n < 20'000; ++n) {
            const Vec4 p1 = hsr::test::random_point(rng, s), p2 = hsr::test::random_point(rng, s);
            const auto d = drain(cohen_sutherland({n, p1, p2}, {.space = s}));
            std::size_t rounds = 0;
            for (const auto& e : d.events) {
                rounds += std::holds_alternative<IntersectionComputed>(e);
                CHECK_FALSE(std::holds_alternative<StepBoundReached>(e));
            }
            most = std::max(most, rounds);
        }
        CHECK(most <= std::size_t(plane_count(s)));
    }
}

TEST_CASE("a machine stopped by its step bound says so in an event", "[clipping][bound]") {
    SECTION("Cohen–Sutherland with room for one round only") {
        const auto d = drain(cohen_sutherland({1, pt(-3, -3, 0), pt(3, 3, 0)}, {.space = ClipSpace::cube, .max_rounds = 1}));
        REQUIRE(std::holds_alternative<StepBoundReached>(d.events.end()[-2]));
        CHECK(std::get<StepBoundReached>(d.events.end()[-2]).bound == Bound::rounds);
        CHECK(d.result.bounded);
    }
    SECTION("Sutherland–Hodgman given a polygon larger than its bound") {
        std::vector<Vec4> many(100, pt(0, 0, 0));
        const auto d = drain(sutherland_hodgman({1, many}, {.space = ClipSpace::cube, .max_vertices = 10}));
        REQUIRE(std::holds_alternative<StepBoundReached>(d.events[1]));
        CHECK(std::get<StepBoundReached>(d.events[1]).limit == 10);
        CHECK(d.result.bounded);
    }
}

TEST_CASE("NaN or infinite input is refused at the door with the coordinate named", "[clipping][input]") {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(cohen_sutherland({4, pt(0, nan, 0), pt(0, 0, 0)}), "segment 4 p1.y is NaN");
    CHECK_THROWS_WITH(liang_barsky({5, pt(0, 0, 0), pt(0, 0, 0, inf)}), "segment 5 p2.w is infinite");
    CHECK_THROWS_WITH(sutherland_hodgman({6, {pt(0, 0, 0), pt(1, 0, 0), pt(0, -inf, 0)}}),
                      "polygon 6 vertex 2.y is infinite");
    CHECK_THROWS_AS(clip_point({7, pt(nan, 0, 0)}), InvalidInput);
}

TEST_CASE("Sutherland–Hodgman emits by the four edge cases", "[clipping][sh]") {
    // A triangle poking out of x ≤ 1: one vertex outside, so stage x max sees in→out, out→in and in→in.
    const auto d = drain(sutherland_hodgman({1, {pt(0, 0, 0), pt(2, 0.5, 0), pt(0, 0.9, 0)}}, {.space = ClipSpace::cube}));
    INFO(narrate(d.events, ClipSpace::cube));
    std::vector<EdgeCase> at_x_max;
    for (const auto& e : d.events)
        if (const auto* c = std::get_if<EdgeClassified>(&e); c && c->plane == ClipPlane::x_max)
            at_x_max.push_back(c->edge_case);
    std::sort(at_x_max.begin(), at_x_max.end());  // the stage's input starts wherever the previous stage left it
    CHECK(at_x_max == std::vector<EdgeCase>{EdgeCase::in_in, EdgeCase::in_out, EdgeCase::out_in});
    CHECK(d.result.vertices.size() == 4);
    CHECK(d.result.outcome == ClipOutcome::clipped);
    const auto whole_out = drain(sutherland_hodgman({2, {pt(2, 0, 0), pt(3, 0, 0), pt(2, 1, 0)}}, {.space = ClipSpace::cube}));
    CHECK(whole_out.result.outcome == ClipOutcome::rejected);
}

TEST_CASE("describe gives the lecture's sentence with the live numbers", "[clipping][describe]") {
    const CodesCompared e{Outcode{0b010010}, Outcode{0}};
    CHECK(describe(e, ClipSpace::cube) ==
          "p1 outcode 010010, p2 outcode 000000: OR = 010010, not trivially accepted; AND = 000000, not trivially "
          "rejected");
}
