// SPDX-License-Identifier: MIT
// The clipping machines against exact rational clipping (GMP) on families of input built to break clippers: through
// corners, along planes, crossing w = 0 and 0 < w < ε, near-parallel to a face at 1e-12 … 1e-16 after another plane
// cut first, huge and tiny, near the double limit, and the known 2D failures of other libraries lifted to 3D (a
// segment along a rectangle's edge, a zero-length segment, fractional bounds). Errors are in ulps of the input's
// largest coordinate; a decision (visible or not) may differ from the exact one only where the exact answer, or the
// machine's, is within a few ulps of touching the volume.
//
// Polygons are compared as regions (score_polygon says why), segments end to end.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <string>

#include "analysis/exact_clip.h"
#include "catch.h"
#include "clipping/cohen_sutherland.h"
#include "clipping/liang_barsky.h"
#include "clipping/sutherland_hodgman.h"
#include "core/numeric.h"

using namespace hsr::algo;
using hsr::analysis::ExactPoint;
using hsr::analysis::exact_clip_polygon;
using hsr::analysis::exact_clip_segment;

namespace {

using Real = long double;  // for measuring only: 11 more bits than the machines' doubles
using Point = std::array<Real, 4>;

constexpr Real kRoundingLevel = 16;  // ulps: a decision may differ from the exact one only this close to touching

struct Case {
    Vec4 a, b;                  // a segment
    std::vector<Vec4> polygon;  // and a polygon
};

Point to_real(const Vec4& v) { return {Real(v.x), Real(v.y), Real(v.z), Real(v.w)}; }
Point to_real(const ExactPoint& p) {
    Point r;
    for (int i = 0; i < 4; ++i) r[std::size_t(i)] = Real(p.c[i].get_d()) + Real(mpq_class(p.c[i] - p.c[i].get_d()).get_d());
    return r;
}

Real ulp_of_largest(const std::vector<Vec4>& inputs) {
    double m = 0;
    for (const Vec4& v : inputs)
        for (int i = 0; i < 4; ++i) m = std::max(m, std::fabs(v[i]));
    return Real(std::nextafter(m, INFINITY) - m);  // the spacing of doubles at the largest coordinate (> 0 even at 0)
}

Real distance(const Point& a, const Point& b) {
    Real d = 0;
    for (std::size_t i = 0; i < 4; ++i) d = std::max(d, std::fabs(a[i] - b[i]));
    return d;
}

// The distance from p to segment ab (Euclidean in the 4 coordinates).
Real to_segment(const Point& p, const Point& a, const Point& b) {
    Real ab2 = 0, t = 0;
    for (std::size_t i = 0; i < 4; ++i) ab2 += (b[i] - a[i]) * (b[i] - a[i]), t += (p[i] - a[i]) * (b[i] - a[i]);
    t = ab2 > 0 ? std::clamp(t / ab2, Real(0), Real(1)) : 0;
    Real d2 = 0;
    for (std::size_t i = 0; i < 4; ++i) {
        const Real e = p[i] - (a[i] + t * (b[i] - a[i]));
        d2 += e * e;
    }
    return std::sqrt(d2);
}

Real to_outline(const Point& p, const std::vector<Point>& outline) {
    Real best = INFINITY;
    for (std::size_t i = 0; i < outline.size(); ++i)
        best = std::min(best, to_segment(p, outline[i], outline[(i + 1) % outline.size()]));
    return best;
}

Real dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]; }
Point minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2], a[3] - b[3]}; }
Point axpy(Real k, const Point& x, const Point& y) { return {k * x[0] + y[0], k * x[1] + y[1], k * x[2] + y[2], k * x[3] + y[3]}; }

// The distance from p to triangle abc as a region: solved for p ≈ o + α e1 + β e2 from the corner o opposite the
// longest side (the best-conditioned pair of sides, even for a needle), the residual when α, β ≥ 0 and α + β ≤ 1.
Real to_triangle(const Point& p, const Point& a, const Point& b, const Point& c) {
    Real best = std::min({to_segment(p, a, b), to_segment(p, b, c), to_segment(p, c, a)});
    const Point* corner[3] = {&a, &b, &c};
    const Real side[3] = {distance(b, c), distance(c, a), distance(a, b)};  // side[i] is opposite corner i
    const int i = int(std::max_element(side, side + 3) - side);
    const Point& o = *corner[i];
    const Point e1 = minus(*corner[(i + 1) % 3], o), e2 = minus(*corner[(i + 2) % 3], o), d = minus(p, o);
    const Real g11 = dot(e1, e1), g12 = dot(e1, e2), g22 = dot(e2, e2), det = g11 * g22 - g12 * g12;
    if (!(det > 0)) return best;  // no area: its sides are the region
    const Real r1 = dot(d, e1), r2 = dot(d, e2);
    const Real alpha = (r1 * g22 - r2 * g12) / det, beta = (r2 * g11 - r1 * g12) / det;
    if (alpha >= 0 && beta >= 0 && alpha + beta <= 1) {
        const Point off = minus(d, axpy(alpha, e1, axpy(beta, e2, Point{})));
        best = std::min(best, std::sqrt(dot(off, off)));
    }
    return best;
}

// The distance from p to a convex polygon as a region (a fan of triangles; its outline when it has fewer than 3).
Real to_region(const Point& p, const std::vector<Point>& polygon) {
    Real best = to_outline(p, polygon);
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
        best = std::min(best, to_triangle(p, polygon[0], polygon[i], polygon[i + 1]));
    return best;
}

// How far outside the clip volume p lies (0 inside): the largest negative boundary value.
Real outside_by(const Point& p, ClipSpace s) {
    const Real w = s == ClipSpace::homogeneous ? p[3] : 1;
    Real worst = 0;
    for (int k = 0; k < 3; ++k) worst = std::max({worst, p[std::size_t(k)] - w, -w - p[std::size_t(k)]});
    if (s == ClipSpace::homogeneous) worst = std::max(worst, Real(ClipTolerance::w_epsilon) - p[3]);
    return worst;
}

Real extent(const std::vector<Point>& points) {
    Real e = 0;
    for (const Point& a : points)
        for (const Point& b : points) e = std::max(e, distance(a, b));
    return e;
}

// How thin a set of points is: the largest distance of one from the line through the two farthest apart.
Real width(const std::vector<Point>& points) {
    Point a{}, b{};
    Real far = -1;
    for (const Point& p : points)
        for (const Point& q : points)
            if (distance(p, q) > far) far = distance(p, q), a = p, b = q;
    Real w = 0;
    for (const Point& p : points) w = std::max(w, to_segment(p, a, b));
    return w;
}

struct Tally {
    int cases = 0, visible = 0, wrong = 0, slivers = 0;
    Real worst_ulps = 0;
    std::string worst_case;
};

std::string show(const std::vector<Vec4>& points) {
    std::string out;
    char text[128];
    for (const Vec4& p : points) {
        std::snprintf(text, sizeof text, "[%.17g, %.17g, %.17g, %.17g] ", p.x, p.y, p.z, p.w);
        out += text;
    }
    return out;
}

void note(Tally& t, Real ulps, const std::vector<Vec4>& input) {
    if (ulps > t.worst_ulps) t.worst_ulps = ulps, t.worst_case = show(input);
}

bool finite(const std::vector<Vec4>& points) {
    return std::all_of(points.begin(), points.end(), [](const Vec4& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
    });
}

void score_segment(Tally& t, const SegmentClip& got, const Vec4& a, const Vec4& b, ClipSpace s) {
    const auto exact = exact_clip_segment(a, b, s);
    const Real ulp = ulp_of_largest({a, b});
    const bool visible = got.outcome != ClipOutcome::rejected;
    ++t.cases;
    t.visible += exact.visible;
    if (visible && !finite({got.a, got.b})) {
        ++t.wrong, note(t, INFINITY, {a, b});
        return;
    }
    if (visible != exact.visible) {
        // a wrong decision unless the exact piece, or the machine's, is within rounding of touching the volume
        const Real off = exact.visible ? distance(to_real(exact.a), to_real(exact.b))
                                       : std::max(outside_by(to_real(got.a), s), outside_by(to_real(got.b), s));
        if (off > kRoundingLevel * ulp) ++t.wrong, note(t, off / ulp, {a, b});
        return;
    }
    if (!visible) return;
    note(t, std::max(distance(to_real(got.a), to_real(exact.a)), distance(to_real(got.b), to_real(exact.b))) / ulp,
         {a, b});
}

// A polygon's error: what is visible and missing (an exact vertex far from the machine's polygon), or what was
// added (a vertex of the machine's polygon off the input polygon or outside the volume). Not vertex to vertex: a
// visible part thinner than an ulp along an edge of the volume may end anywhere along it in rounding, and the answer
// is still the exact clip of an input within an ulp of the one given.
void score_polygon(Tally& t, const PolygonClip& got, const std::vector<Vec4>& polygon, ClipSpace s) {
    const auto exact_points = exact_clip_polygon(polygon, s);
    std::vector<Point> exact, mine, input;
    for (const auto& p : exact_points) exact.push_back(to_real(p));
    for (const auto& p : got.vertices) mine.push_back(to_real(p));
    for (const auto& p : polygon) input.push_back(to_real(p));
    const Real ulp = ulp_of_largest(polygon);
    ++t.cases;
    t.visible += !exact.empty();
    if (!finite(got.vertices)) {
        ++t.wrong, note(t, INFINITY, polygon);
        return;
    }
    Real added = 0, missing = 0;
    for (const Point& p : mine) added = std::max({added, outside_by(p, s), to_region(p, input)});
    if (!exact.empty() && width(exact) <= kRoundingLevel * ulp) {
        ++t.slivers;  // thinner than rounding: which parts of it are visible is decided at rounding level
    } else if (mine.empty()) {
        missing = extent(exact);
    } else {
        for (const Point& p : exact) missing = std::max(missing, to_region(p, mine));
    }
    if (exact.empty() != mine.empty()) {  // a decision: wrong unless within rounding of touching the volume
        if (std::max(added, missing) > kRoundingLevel * ulp) ++t.wrong, note(t, std::max(added, missing) / ulp, polygon);
        return;
    }
    note(t, std::max(added, missing) / ulp, polygon);
}

bool finite_or_rejected(const SegmentClip& c) { return c.outcome == ClipOutcome::rejected || finite({c.a, c.b}); }

// ---- the families ----

using Rng = std::mt19937_64;
double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
int pick(Rng& rng, int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); }
double sign(Rng& rng) { return pick(rng, 2) ? 1.0 : -1.0; }

Vec4 with_w(Vec4 v, double w, ClipSpace s) {  // v's x, y, z given for w = 1, scaled to w in homogeneous clip space
    if (s == ClipSpace::cube) return {v.x, v.y, v.z, 1};
    return {v.x * w, v.y * w, v.z * w, w};
}
double random_w(Rng& rng) { return uniform(rng, 0.25, 4); }
Vec4 random_unit(Rng& rng, double range) { return {uniform(rng, -range, range), uniform(rng, -range, range), uniform(rng, -range, range), 1}; }

// A triangle on the segment, so the polygon shares the segment's difficulty.
std::vector<Vec4> around(Rng& rng, const Vec4& a, const Vec4& b, double spread) {
    Vec4 c = (a + b) * 0.5;
    c[pick(rng, 3)] += spread * sign(rng);
    return {a, b, c};
}

// Segments through a corner (or the middle of an edge) of the volume.
Case through_corners(Rng& rng, ClipSpace s) {
    const double w = random_w(rng);
    Vec4 corner{sign(rng), sign(rng), sign(rng), 1};
    if (pick(rng, 3) == 0) corner[pick(rng, 3)] = 0;  // the middle of an edge
    const Vec4 d = random_unit(rng, 1);
    const double k1 = uniform(rng, 0.1, 2), k2 = uniform(rng, 0.1, 2);
    const Vec4 a = with_w({corner.x - k1 * d.x, corner.y - k1 * d.y, corner.z - k1 * d.z, 1}, w, s);
    const Vec4 b = with_w({corner.x + k2 * d.x, corner.y + k2 * d.y, corner.z + k2 * d.z, 1}, w, s);
    return {a, b, around(rng, a, b, 0.5 * w)};
}

// Segments and polygons lying in a face (x = ±w …), partly beyond its edges.
Case along_planes(Rng& rng, ClipSpace s) {
    const int axis = pick(rng, 3);
    const double side = sign(rng);
    auto on_face = [&] {
        Vec4 v = random_unit(rng, 2);
        v[axis] = side;
        return v;
    };
    const double w = random_w(rng);
    const Vec4 a = with_w(on_face(), w, s), b = with_w(on_face(), w, s), c = with_w(on_face(), w, s);
    return {a, b, {a, b, c}};
}

// Across w = 0, and into 0 < w < ε (homogeneous only; the cube has no w).
Case crossing_w0(Rng& rng, ClipSpace s) {
    static constexpr double tiny_w[] = {0.0, 1e-12, 5e-10, 1e-9, 2e-9, -1e-300, 1e-300};
    const Vec4 u = random_unit(rng, 1.2), v = random_unit(rng, 1.2), q = random_unit(rng, 1.2);
    const double wa = pick(rng, 2) ? tiny_w[pick(rng, 7)] : -random_w(rng);
    const double wb = random_w(rng), wc = pick(rng, 2) ? tiny_w[pick(rng, 7)] : -random_w(rng);
    const Vec4 a = s == ClipSpace::cube ? u : Vec4{u.x, u.y, u.z, wa};
    const Vec4 b = with_w(v, wb, s);
    const Vec4 c = s == ClipSpace::cube ? q : Vec4{q.x, q.y, q.z, wc};
    return {a, b, {a, b, c}};
}

// From just inside to just outside a face, 1e-12 … 1e-16 of the scale, with another plane cutting first.
Case near_parallel(Rng& rng, ClipSpace s) {
    const double w = random_w(rng);
    const int axis = pick(rng, 2), cutter = 2;  // x or y face, cut first by a z plane (z is tested before them)
    const double face = sign(rng);
    const double d1 = std::pow(10.0, -uniform(rng, 12, 16.5)), d2 = std::pow(10.0, -uniform(rng, 12, 16.5));
    Vec4 p{0, 0, 0, 1}, q{0, 0, 0, 1};
    p[axis] = face * (1 - d1), q[axis] = face * (1 + d2);
    p[1 - axis] = q[1 - axis] = uniform(rng, -0.9, 0.9);
    p[cutter] = sign(rng) * uniform(rng, 1.01, 3), q[cutter] = -p[cutter] * uniform(rng, 0.2, 1.5);
    const Vec4 a = with_w(p, w, s), b = with_w(q, w, s);
    Vec4 a2 = a, b2 = b;  // the polygon: the segment swept across the face
    const double wide = uniform(rng, 0.2, 1) * (s == ClipSpace::cube ? 1 : w);
    a2[1 - axis] += wide, b2[1 - axis] += wide;
    return {a, b, {a, b, b2, a2}};
}

// Coordinates from 1e-300 to 1e300, each end its own scale.
Case huge_and_tiny(Rng& rng, ClipSpace s) {
    auto scaled = [&] {
        const double k = std::pow(10.0, uniform(rng, -300, 300));
        Vec4 v = random_unit(rng, 3) * k;  // w = k too, scaled below
        v.w = s == ClipSpace::cube ? 1 : pick(rng, 2) ? k : std::pow(10.0, uniform(rng, -300, 300));
        if (s == ClipSpace::homogeneous && pick(rng, 2)) v.w = std::fabs(v.x);  // on a face
        return v;
    };
    const Vec4 a = scaled(), b = scaled(), c = scaled();
    return {a, b, {a, b, c}};
}

// Coordinates near the largest a clipper takes (ClipTolerance::largest_coordinate), and small ones beside them.
Case near_the_limit(Rng& rng, ClipSpace s) {
    const double m = ClipTolerance::largest_coordinate;
    auto big = [&] {
        Vec4 v;
        for (int i = 0; i < 4; ++i) v[i] = pick(rng, 3) ? sign(rng) * m * uniform(rng, 0.5, 1) : uniform(rng, -2, 2);
        v.w = s == ClipSpace::cube ? 1 : pick(rng, 2) ? m * uniform(rng, 0.5, 1) : uniform(rng, 0.5, 2);
        return v;
    };
    const Vec4 a = big(), b = big(), c = big();
    return {a, b, {a, b, c}};
}

// Failures of 2D clippers in other libraries, lifted: a segment along an edge of the volume (two faces at once),
// a zero-length segment (inside, outside or on a face), and fractional bounds (w = 0.1, 0.3, 0.7 are not doubles)
// with coordinates at ±w computed from them.
Case lifted_2d(Rng& rng, ClipSpace s) {
    static constexpr double fractional[] = {0.1, 0.3, 0.7, 1.0 / 3, 2.0 / 3};
    const double w = s == ClipSpace::cube ? 1 : fractional[pick(rng, 5)];
    switch (pick(rng, 3)) {
        case 0: {  // along an edge: x = w, y = w, z runs past both ends
            const double sx = sign(rng), sy = sign(rng);
            const Vec4 a{sx * w, sy * w, -uniform(rng, 0.5, 3) * w, w}, b{sx * w, sy * w, uniform(rng, 0.5, 3) * w, w};
            return {a, b, {a, b, Vec4{sx * w * 0.5, sy * w, 0, w}}};
        }
        case 1: {  // zero length
            Vec4 p = random_unit(rng, 1.5);
            if (pick(rng, 2)) p[pick(rng, 3)] = sign(rng);
            const Vec4 a = with_w(p, w, s);
            return {a, a, {a, a, a}};
        }
        default: {  // fractional bounds: ends at 3·(w/3)-style values a rounding away from ±w
            Vec4 p = random_unit(rng, 2) * w, q = random_unit(rng, 2) * w;
            p.w = q.w = w;
            p[pick(rng, 3)] = sign(rng) * (w / 3) * 3;
            q[pick(rng, 3)] = sign(rng) * (w * 0.1) * 10;
            return {p, q, {p, q, Vec4{-p.x, q.y, p.z, w}}};
        }
    }
}

struct Family {
    const char* name;
    std::function<Case(Rng&, ClipSpace)> make;
};
const Family families[] = {{"through corners", through_corners}, {"along planes", along_planes},
                           {"crossing w = 0", crossing_w0},      {"near-parallel", near_parallel},
                           {"huge and tiny", huge_and_tiny},     {"near the limit", near_the_limit},
                           {"lifted 2D", lifted_2d}};

}  // namespace

TEST_CASE("the clipping machines against exact rational clipping on adversarial families", "[clipping][exact][adversarial]") {
    constexpr int kCases = 1500;  // per family and setting
    std::map<std::string, Tally> total;
    for (const ClipSpace s : {ClipSpace::cube, ClipSpace::homogeneous}) {
        for (const Family& family : families) {
            Rng rng(std::hash<std::string>{}(family.name) ^ (s == ClipSpace::cube ? 1 : 2));
            Tally cs, lb, sh;
            for (int n = 0; n < kCases; ++n) {
                const Case c = family.make(rng, s);
                score_segment(cs, cohen_sutherland({n, c.a, c.b}, {.space = s}).run_to_end(), c.a, c.b, s);
                score_segment(lb, liang_barsky({n, c.a, c.b}, {.space = s}).run_to_end(), c.a, c.b, s);
                score_polygon(sh, sutherland_hodgman({n, c.polygon}, {.space = s}).run_to_end(), c.polygon, s);
            }
            const std::string setting = s == ClipSpace::cube ? "cube" : "homogeneous";
            for (const auto& [name, t] : {std::pair{"cohen_sutherland", &cs}, std::pair{"liang_barsky", &lb},
                                          std::pair{"sutherland_hodgman", &sh}}) {
                INFO(name << ", " << family.name << ", " << setting << ": worst case " << t->worst_case);
                CHECK(t->wrong == 0);
                CHECK(t->worst_ulps <= 64);
                std::printf("  %-19s %-16s %-11s %5d cases, %5d visible (%d thinner than rounding), largest error %6.2Lf ulps, %d wrong decisions\n",
                            name, family.name, setting.c_str(), t->cases, t->visible, t->slivers, t->worst_ulps, t->wrong);
                Tally& all = total[name];
                all.cases += t->cases, all.visible += t->visible, all.wrong += t->wrong, all.slivers += t->slivers;
                if (t->worst_ulps > all.worst_ulps) all.worst_ulps = t->worst_ulps, all.worst_case = t->worst_case;
            }
        }
    }
    for (const auto& [name, t] : total)
        std::printf("clipping adversarial: %-19s %6d cases, %6d visible (%d thinner than rounding), largest error %.2Lf ulps of the largest input coordinate, %d wrong decisions\n",
                    name.c_str(), t.cases, t.visible, t.slivers, t.worst_ulps, t.wrong);
}

TEST_CASE("the regression cases of exact clipping: a cut, then a face within an ulp", "[clipping][exact]") {
    // issue 19 bug 5a: re-clipped from a rounded point, CS kept the single point z = 1 and SH a polygon of no area
    const Vec4 a{-0.9999999999999999, 0.0, 1.5, 1.0}, b{-1.0000000000000004, 0.0, -1.5, 1.0};
    for (const ClipSpace s : {ClipSpace::cube, ClipSpace::homogeneous}) {
        const SegmentClip c = cohen_sutherland({1, a, b}, {.space = s}).run_to_end();
        REQUIRE(c.outcome == ClipOutcome::clipped);
        CHECK(c.a == Vec4{-1, 0, 1, 1});
        CHECK(std::fabs(c.b.z - 0.9) < 1e-15);
        const PolygonClip p = sutherland_hodgman({2, {a + Vec4{0, -0.5, 0, 0}, b + Vec4{0, -0.5, 0, 0},
                                                      b + Vec4{0, 0.5, 0, 0}, a + Vec4{0, 0.5, 0, 0}}},
                                                 {.space = s})
                                  .run_to_end();
        REQUIRE(p.vertices.size() == 4);
        double z_lo = 1;
        for (const Vec4& v : p.vertices) z_lo = std::min(z_lo, v.z);
        CHECK(std::fabs(z_lo - 0.9) < 1e-15);  // a 1 × 0.1 rectangle, not one of no area
    }
}

TEST_CASE("coordinates a clipper cannot take are refused, naming the coordinate, up to the limit nothing is NaN", "[clipping][limits]") {
    // issue 19 bug 5b: w − z overflowed; CS answered NaN endpoints and LB "inside" with endpoints outside the volume
    const Vec4 a{0, 0, 1.5e308, 1e308}, b{0, 0, -1.5e308, 1e308};
    CHECK_THROWS_WITH(cohen_sutherland({1, a, b}).run_to_end(), Catch::Contains("segment 1 p1.z") && Catch::Contains("1e+307"));
    CHECK_THROWS_WITH(liang_barsky({1, a, b}).run_to_end(), Catch::Contains("segment 1 p1.z"));
    CHECK_THROWS_WITH(sutherland_hodgman({3, {a, b, Vec4{0, 1, 0, 1}}}).run_to_end(), Catch::Contains("polygon 3 vertex 0.z"));
    const double m = ClipTolerance::largest_coordinate;
    for (const double sz : {1.0, -1.0}) {
        const Vec4 p{-m, m, sz * m, m}, q{m, -m, -sz * m, -m};  // every boundary value at its largest, both signs
        for (const SegmentClip& c : {cohen_sutherland({1, p, q}).run_to_end(), liang_barsky({1, p, q}).run_to_end()}) {
            CHECK(finite_or_rejected(c));
        }
        const PolygonClip poly = sutherland_hodgman({2, {p, q, Vec4{m, m, m, m}}}).run_to_end();
        for (const Vec4& v : poly.vertices) CHECK((std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w)));
    }
}
