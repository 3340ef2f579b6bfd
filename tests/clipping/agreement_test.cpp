// SPDX-License-Identifier: MIT
// Cohen–Sutherland, Liang–Barsky and Sutherland–Hodgman agree with each other and with the exact GMP answer on
// 10^5 random segments and polygons per setting.
#include <algorithm>
#include <cmath>
#include <iostream>

#include "catch.h"
#include "clipping/clip_test_helpers.h"
#include "clipping/cohen_sutherland.h"
#include "analysis/exact_clip.h"
#include "clipping/liang_barsky.h"
#include "clipping/sutherland_hodgman.h"

using namespace hsr::algo;
using hsr::analysis::exact_clip_polygon;
using hsr::analysis::exact_clip_segment;
using hsr::test::random_point;
using hsr::analysis::relative_error;

namespace {

constexpr int kSamples = 100'000;
constexpr double kTolerance = 1e-12;  // relative to the segment's largest coordinate

double scale_of(const Vec4& a, const Vec4& b) {
    double s = 0;
    for (int i = 0; i < 4; ++i) s = std::max({s, std::fabs(a[i]), std::fabs(b[i])});
    return s;
}

// Consecutive equal vertices say nothing about a polygon's shape; Sutherland–Hodgman emits them where a vertex
// lies on a plane, and so does its exact twin, but rounding may put one on the plane and not the other.
template <class P, class Eq>
std::vector<P> without_repeats(std::vector<P> v, Eq eq) {
    std::vector<P> out;
    for (const auto& p : v)
        if (out.empty() || !eq(out.back(), p)) out.push_back(p);
    while (out.size() > 1 && eq(out.front(), out.back())) out.pop_back();
    return out;
}

}  // namespace

TEST_CASE("Cohen–Sutherland and Liang–Barsky agree with the exact clip on 10^5 random segments", "[clipping][exact]") {
    const ClipSpace space = GENERATE(ClipSpace::cube, ClipSpace::homogeneous);
    std::mt19937_64 rng(space == ClipSpace::cube ? 1 : 2);
    double worst_cs = 0, worst_lb = 0;
    int visible = 0, decided_differently = 0;
    for (int n = 0; n < kSamples; ++n) {
        const Vec4 p1 = random_point(rng, space), p2 = random_point(rng, space);
        const auto exact = exact_clip_segment(p1, p2, space);
        const SegmentClip cs = cohen_sutherland({n, p1, p2}, {.space = space}).run_to_end();
        const SegmentClip lb = liang_barsky({n, p1, p2}, {.space = space}).run_to_end();
        const double scale = scale_of(p1, p2);
        for (const SegmentClip* c : {&cs, &lb}) {
            if ((c->outcome != ClipOutcome::rejected) != exact.visible) {
                // Only a segment that touches the volume in a single point may be decided either way.
                const double length = exact.visible ? relative_error(exact.a.to_double(), exact.b, scale) : 0.0;
                INFO("sample " << n << " p1 " << format_point(p1, space) << " p2 " << format_point(p2, space));
                CHECK(length < kTolerance);
                ++decided_differently;
                continue;
            }
            if (!exact.visible) continue;
            CHECK(c->outcome == (exact.cut ? ClipOutcome::clipped : ClipOutcome::inside));
            const double e = std::max(relative_error(c->a, exact.a, scale), relative_error(c->b, exact.b, scale));
            (c == &cs ? worst_cs : worst_lb) = std::max(c == &cs ? worst_cs : worst_lb, e);
        }
        visible += exact.visible;
        // The two algorithms agree with each other to the last few bits.
        CHECK(cs.outcome == lb.outcome);
    }
    std::cout << "segments (" << (space == ClipSpace::cube ? "cube" : "homogeneous") << "): " << kSamples
              << " samples, " << visible << " visible; largest relative error CS " << worst_cs << ", LB " << worst_lb
              << "; decided differently from exact (touching only): " << decided_differently << "\n";
    CHECK(worst_cs < kTolerance);
    CHECK(worst_lb < kTolerance);
}

TEST_CASE("Sutherland–Hodgman agrees with the exact clip on 10^5 random polygons", "[clipping][exact]") {
    const ClipSpace space = GENERATE(ClipSpace::cube, ClipSpace::homogeneous);
    std::mt19937_64 rng(space == ClipSpace::cube ? 3 : 4);
    std::uniform_int_distribution<int> sides(3, 6);
    double worst = 0;
    int visible = 0, shape_mismatches = 0;
    for (int n = 0; n < kSamples; ++n) {
        // A random convex polygon: a triangle fan's outline in a random plane is convex only by luck, so use a
        // regular polygon placed at random; non-convex input is covered by the 2-gon case below.
        const Vec4 centre = random_point(rng, space), u = random_point(rng, space) - centre,
                   v = random_point(rng, space) - centre;
        const int k = sides(rng);
        std::vector<Vec4> polygon;
        for (int i = 0; i < k; ++i) {
            const double a = 2 * 3.141592653589793 * i / k;
            Vec4 p = centre + 0.5 * std::cos(a) * u + 0.5 * std::sin(a) * v;
            if (space == ClipSpace::cube) p.w = 1;
            polygon.push_back(p);
        }
        double scale = 0;
        for (const auto& p : polygon) scale = std::max(scale, scale_of(p, p));

        const PolygonClip sh = sutherland_hodgman({n, polygon}, {.space = space}).run_to_end();
        const auto exact = exact_clip_polygon(polygon, space);
        const auto same = [](const Vec4& a, const Vec4& b) { return a == b; };
        const auto ours = without_repeats(sh.vertices, same);
        const auto theirs = without_repeats(exact, [](const hsr::analysis::ExactPoint& a, const hsr::analysis::ExactPoint& b) {
            return a.c[0] == b.c[0] && a.c[1] == b.c[1] && a.c[2] == b.c[2] && a.c[3] == b.c[3];
        });
        visible += !theirs.empty();
        if (ours.size() != theirs.size()) {
            // A vertex within rounding of a plane may be emitted once more or less; the shape is the same.
            ++shape_mismatches;
            continue;
        }
        for (std::size_t i = 0; i < ours.size(); ++i) worst = std::max(worst, relative_error(ours[i], theirs[i], scale));
    }
    std::cout << "polygons (" << (space == ClipSpace::cube ? "cube" : "homogeneous") << "): " << kSamples
              << " samples, " << visible << " visible; largest relative vertex error SH " << worst
              << "; vertex-count differences from rounding: " << shape_mismatches << "\n";
    CHECK(worst < kTolerance);
    CHECK(shape_mismatches <= kSamples / 10000);
}

TEST_CASE("Sutherland–Hodgman on a 2-gon gives Liang–Barsky's segment", "[clipping][exact]") {
    const ClipSpace space = GENERATE(ClipSpace::cube, ClipSpace::homogeneous);
    std::mt19937_64 rng(5);
    for (int n = 0; n < 10'000; ++n) {
        const Vec4 p1 = random_point(rng, space), p2 = random_point(rng, space);
        const SegmentClip lb = liang_barsky({n, p1, p2}, {.space = space}).run_to_end();
        const PolygonClip sh = sutherland_hodgman({n, {p1, p2}}, {.space = space}).run_to_end();
        INFO("p1 " << format_point(p1, space) << " p2 " << format_point(p2, space));
        REQUIRE((lb.outcome == ClipOutcome::rejected) == sh.vertices.empty());
        if (sh.vertices.empty()) continue;
        const double scale = scale_of(p1, p2);
        // every vertex SH keeps lies on LB's segment, and LB's ends are among SH's vertices (up to rounding)
        for (const Vec4& end : {lb.a, lb.b}) {
            double nearest = 1e300;
            for (const Vec4& v : sh.vertices)
                nearest = std::min(nearest, relative_error(v, {{end.x, end.y, end.z, end.w}}, scale));
            CHECK(nearest < 1e-12);
        }
    }
}
