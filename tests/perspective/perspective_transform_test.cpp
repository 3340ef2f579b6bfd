// SPDX-License-Identifier: MIT
// The perspective transform's occluding pairs against exact rationals (GMP): every double is a rational, so whether
// two eye-space points lie on one projector (x_a·z_b = x_b·z_a and y_a·z_b = y_b·z_a) and which is nearer can be
// decided with no rounding at all. The machine decides in doubles, both ways (x/z before, x′ after the divide by
// w); it must agree with the exact answer wherever the exact gap is 0 or clearly not. The warp the window draws is
// checked for what the notes say of the transform: lines stay lines, the frustum becomes the box, the eye goes to
// infinity and the projectors become parallel, "in front of" is kept.
#include <cmath>
#include <random>

#include <gmpxx.h>

#include "catch.h"
#include "core/numeric.h"
#include "perspective/perspective_transform.h"

using namespace hsr::algo;

namespace {

// A camera at the origin looking down −z with y up: its look-at is exactly the identity, so a world point is its
// own eye-space point and the exact reference sees the very numbers the machine starts from.
Scene eye_at_origin(bool orthographic = false, double near = 1, double far = 10) {
    Scene s;
    s.camera.eye = {0, 0, 0}, s.camera.target = {0, 0, -1}, s.camera.near = near, s.camera.far = far;
    s.camera.fov_y = 60, s.camera.aspect = 1.5;
    if (orthographic) {
        s.camera.projection = Projection::orthographic;
        s.camera.box[0] = -3, s.camera.box[1] = 3, s.camera.box[2] = -2, s.camera.box[3] = 2;
    }
    return s;
}
void add_point(Scene& s, Vec3 p) { s.points.push_back({SceneId(s.points.size() + 1), {}, glm::dvec4(p, 1)}); }

mpq_class q(double v) { return mpq_class(v); }

// How far apart two eye-space points' projectors are, exactly: the larger difference of x/z and y/z (orthographic: of
// x and y), relative to the larger of 1 and the numbers compared; 0 exactly when they share a projector.
double exact_gap(Vec3 a, Vec3 b, bool perspective) {
    const auto rel = [](const mpq_class& u, const mpq_class& v) {
        const mpq_class d = abs(u - v);
        const mpq_class scale = std::max({mpq_class(1), mpq_class(abs(u)), mpq_class(abs(v))});
        return mpq_class(d / scale).get_d();
    };
    if (!perspective) return std::max(rel(q(a.x), q(b.x)), rel(q(a.y), q(b.y)));
    return std::max(rel(q(a.x) / q(a.z), q(b.x) / q(b.z)), rel(q(a.y) / q(a.z), q(b.y) / q(b.z)));
}

struct Run {
    std::vector<TransformEvent> events;
    TransformResult result;
};
Run run(const Scene& s, TransformOptions o = {}) {
    Run r;
    auto steps = perspective_transform(s, o);
    for (const auto& e : steps) r.events.push_back(e);
    r.result = steps.result();
    return r;
}
template <class E>
std::vector<E> all_of(const Run& r) {
    std::vector<E> out;
    for (const auto& e : r.events)
        if (const auto* x = std::get_if<E>(&e)) out.push_back(*x);
    return out;
}

// Pairs built to test the projector decision: exactly on one projector (scaled by a power of two), on it but for
// rounding (scaled by any number), near it (off by a relative 1e-6) and anywhere.
Scene projector_pairs(std::uint32_t seed, bool orthographic, double near = 1, double far = 10) {
    Scene s = eye_at_origin(orthographic, near, far);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1), depth(near * 1.01, far * 0.45), k(0.5, 2);
    for (int i = 0; i < 12; ++i) {
        const double z = -depth(rng);
        const Vec3 p(unit(rng) * -z * 0.5, unit(rng) * -z * 0.5, z);
        add_point(s, p);
        const double scale = orthographic ? 1 : (i % 4 == 0 ? 2.0 : i % 4 == 1 ? k(rng) : 1.5);
        Vec3 other = orthographic ? Vec3(p.x, p.y, p.z * k(rng)) : p * scale;
        if (i % 4 == 2) other.x *= 1 + 1e-6;                    // near: just off the projector
        if (i % 4 == 3) other = Vec3(unit(rng), unit(rng), -depth(rng));  // anywhere
        add_point(s, other);
    }
    return s;
}

}  // namespace

TEST_CASE("Occluding pairs agree with exact rationals, both before and after the transform", "[perspective]") {
    for (const bool orthographic : {false, true})
        for (std::uint32_t seed = 1; seed <= 8; ++seed) {
            const Scene s = projector_pairs(seed, orthographic);
            const Run r = run(s);
            std::size_t exact_pairs = 0, checked = 0;
            for (const PairCompared& c : all_of<PairCompared>(r)) {
                const Vec3 a = r.result.eye[c.a], b = r.result.eye[c.b];
                REQUIRE(a == Vec3(s.points[c.a].p));  // the look-at is the identity: the reference's input is exact
                const double gap = exact_gap(a, b, !orthographic);
                INFO("seed " << seed << (orthographic ? " orthographic" : " perspective") << ", points " << c.a << ", " << c.b << ", gap " << gap);
                if (gap <= 1e-14) {  // on one projector, exactly or but for the rounding of the scaled copy
                    CHECK(c.same_before);
                    CHECK(c.same_after);
                    exact_pairs += gap == 0;
                    ++checked;
                    // the nearer is the one nearer the eye in eye space (larger z): z′ keeps "in front of"
                    if (a.z != b.z) CHECK(c.nearer == (a.z > b.z ? std::int32_t(c.a) : std::int32_t(c.b)));
                } else if (gap >= 1e-10) {
                    CHECK_FALSE(c.same_before);
                    CHECK_FALSE(c.same_after);
                    ++checked;
                }
            }
            CHECK(checked == all_of<PairCompared>(r).size());  // no pair fell in the band between
            CHECK(exact_pairs >= 3);
            const TransformFinished f = all_of<TransformFinished>(r).back();
            CHECK(f.disagreements == 0);
            CHECK(f.comparisons == 24 * 23 / 2);
            CHECK(f.divisions_before == (orthographic ? 0 : 4 * f.comparisons));
            CHECK(f.divisions_after == 3 * 24);
        }
}

TEST_CASE("The tolerance decides: a copy off by less is on the projector, by more is not", "[perspective]") {
    Scene s = eye_at_origin();
    add_point(s, {0.5, 0.25, -2});
    add_point(s, {1, 0.5 * (1 + 1e-14), -4});  // off by 1e-14 relative: within 1e-12
    add_point(s, {1, 0.5 * (1 + 1e-9), -4});   // off by 1e-9: apart
    const auto pairs = all_of<PairCompared>(run(s));
    REQUIRE(pairs.size() == 3);
    CHECK(pairs[0].same_before);
    CHECK(pairs[0].same_after);
    CHECK(pairs[0].nearer == 0);
    CHECK_FALSE(pairs[1].same_before);
    CHECK_FALSE(pairs[1].same_after);
    CHECK_FALSE(pairs[2].same_before);  // 1 and 2 differ by 1e-9 relative in y: apart
    CHECK_FALSE(pairs[2].same_after);
}

TEST_CASE("Equal x and y are no occluding pair in perspective, and are one in orthographic projection", "[perspective]") {
    for (const bool orthographic : {false, true}) {
        Scene s = eye_at_origin(orthographic);
        add_point(s, {1, -0.5, -3});
        add_point(s, {1, -0.5, -6});
        const Run r = run(s);
        const PairCompared c = all_of<PairCompared>(r).at(0);
        CHECK(c.same_after == orthographic);
        CHECK(c.same_before == orthographic);
        if (orthographic) CHECK(c.nearer == 0);
        CHECK(all_of<WarpStep>(r).size() == (orthographic ? 3u : 6u));  // orthographic: stage 2 has nothing to do
    }
}

TEST_CASE("Depths far apart in ratio: z′ may tie, but never turns the order around", "[perspective]") {
    // near 1e-3, far 1e7: z′ crowds toward 1, and two points far out on one projector can get equal z′
    Scene s = eye_at_origin(false, 1e-3, 1e7);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> depth(1, 9e6);
    for (int i = 0; i < 40; ++i) {
        const double z = -depth(rng);
        const Vec3 p(0.25 * z, -0.125 * z, z);
        add_point(s, p);
        add_point(s, p * (1 + std::ldexp(1.0, -30)));  // a power of two apart in depth: exactly on one projector
    }
    const Run r = run(s);
    int ties = 0, ordered = 0;
    for (const PairCompared& c : all_of<PairCompared>(r)) {
        if (!c.same_after) continue;
        const Vec3 a = r.result.eye[c.a], b = r.result.eye[c.b];
        REQUIRE(exact_gap(a, b, true) == 0);
        if (c.nearer < 0) ++ties;
        else {
            CHECK(c.nearer == (a.z > b.z ? std::int32_t(c.a) : std::int32_t(c.b)));
            ++ordered;
        }
    }
    CHECK(ordered > 0);
    CHECK(ties > 0);  // the depth precision lesson's point, seen here as pairs whose z′ are equal
}

TEST_CASE("Points on or behind the eye's plane, and too large for doubles, are left out with no NaN", "[perspective]") {
    Scene s = eye_at_origin();
    add_point(s, {0.5, 0.5, -2});
    add_point(s, {0.5, 0.5, 0});        // on the eye's plane: w = 0
    add_point(s, {0.5, 0.5, 3});        // behind the eye
    add_point(s, {1e308, 0, -1e-300});  // x/z overflows
    add_point(s, {-1e-300, 1e-300, -1e300});
    const Run r = run(s);
    const auto out = all_of<PointLeftOut>(r);
    REQUIRE(out.size() == 3);
    CHECK(out[0].point == 1);
    CHECK(out[0].behind_eye);
    CHECK(out[1].point == 2);
    CHECK(out[2].point == 3);
    CHECK_FALSE(out[2].behind_eye);
    for (const PointTransformed& p : all_of<PointTransformed>(r))
        for (const double v : {p.x, p.y, p.z, p.w, p.nx, p.ny, p.nz}) CHECK(std::isfinite(v));
    for (const PairCompared& c : all_of<PairCompared>(r))
        for (const double v : {c.ratio_ax, c.ratio_ay, c.ratio_bx, c.ratio_by}) CHECK(std::isfinite(v));
    CHECK(all_of<TransformFinished>(r).back().left_out == 3);
    CHECK(all_of<PairCompared>(r).size() == 1);
}

TEST_CASE("The machine stops at its step bound and says so", "[perspective]") {
    Scene s = eye_at_origin();
    for (int i = 0; i < 10; ++i) add_point(s, {0.1 * i, 0, -2 - i});
    const Run r = run(s, {.max_comparisons = 3});
    const TransformFinished f = all_of<TransformFinished>(r).back();
    CHECK(f.bounded);
    CHECK(f.comparisons == 3);
    CHECK(all_of<PairCompared>(r).size() == 3);
    CHECK(describe(TransformEvent(f)).find("step bound") != std::string::npos);
}

TEST_CASE("A scene without points, or in clip coordinates, is refused", "[perspective]") {
    Scene s = eye_at_origin();
    CHECK_THROWS_AS(run(s), InvalidInput);
    add_point(s, {0, 0, -2});
    s.coordinates = Coordinates::clip;
    CHECK_THROWS_AS(run(s), InvalidInput);
}

TEST_CASE("The warp keeps lines straight, ends at the box with the eye at infinity, and keeps depth order", "[perspective]") {
    for (const bool orthographic : {false, true}) {
        Scene s = eye_at_origin(orthographic, 1, 8);
        s.camera.eye = {2, 1, 6}, s.camera.target = {0, 0.5, 0};  // a general camera: the view is not the identity
        const ViewVolumeMaps m = view_volume_maps(s.camera);
        const glm::dmat4 vp = view_projection(s.camera);
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> u(-1, 1);
        // the end of the warp is the transform itself: (x′, y′, −z′)
        for (int i = 0; i < 50; ++i) {
            const Vec3 world(2 * u(rng), 2 * u(rng), 2 * u(rng));
            const glm::dvec4 clip = vp * glm::dvec4(world, 1);
            const Vec3 ndc = Vec3(clip) / clip.w;
            const Vec3 end = *warp(m, 2, 1, Vec3(m.view * glm::dvec4(world, 1)));
            CHECK(glm::length(end - Vec3(ndc.x, ndc.y, -ndc.z)) < 1e-12);
        }
        // the volume's corners end at the box's
        for (const Vec3& corner : view_volume_corners(s.camera)) {
            const Vec3 end = *warp(m, 2, 1, corner);
            for (int k = 0; k < 3; ++k) CHECK(std::abs(std::abs(end[k]) - 1) < 1e-12);
        }
        // three points on a line (inside the volume) stay on a line at every step of both stages, and depth order
        // along a projector is kept
        for (int i = 0; i < 20; ++i) {
            const Vec3 a(u(rng) * 0.5, u(rng) * 0.5, -2 - 5 * std::abs(u(rng))), b(u(rng) * 0.5, u(rng) * 0.5, -2 - 5 * std::abs(u(rng)));
            const Vec3 mid = a + 0.3 * (b - a);
            const Vec3 near_a = orthographic ? a + Vec3(0, 0, 0.5) : a * 0.8;  // on a's projector, nearer the eye
            for (std::uint32_t stage = 1; stage <= 2; ++stage)
                for (double t = 0; t <= 1; t += 0.125) {
                    const Vec3 pa = *warp(m, stage, t, a), pb = *warp(m, stage, t, b), pm = *warp(m, stage, t, mid);
                    CHECK(glm::length(glm::cross(pb - pa, pm - pa)) <= 1e-12 * glm::length(pb - pa) * glm::length(pm - pa) + 1e-15);
                    CHECK(warp(m, stage, t, near_a)->z > pa.z);  // the picture's z grows toward the eye
                }
        }
        // the eye goes to infinity: it has a place until the end of stage 2, where the projectors are parallel
        if (!orthographic) {
            CHECK(warp(m, 2, 0.75, Vec3(0)).has_value());
            CHECK_FALSE(warp(m, 2, 1, Vec3(0)).has_value());
            CHECK(warp(m, 2, 0.75, Vec3(0))->z > warp(m, 2, 0.5, Vec3(0))->z);
            const Vec3 p(0.5, 0.3, -3), far_p = p * 2.0;
            const Vec3 half_a = *warp(m, 2, 0.5, p), half_b = *warp(m, 2, 0.5, far_p);
            CHECK(std::abs(half_a.x - half_b.x) > 0.01);  // part way, the projector still slants
            const Vec3 end_a = *warp(m, 2, 1, p), end_b = *warp(m, 2, 1, far_p);
            CHECK(std::abs(end_a.x - end_b.x) < 1e-12);  // at the end it is parallel to z
            CHECK(std::abs(end_a.y - end_b.y) < 1e-12);
        }
    }
}

TEST_CASE("Stage 1 ends at the canonical volume: sides at 45 degrees, the far plane at z = -1", "[perspective]") {
    const Scene s = eye_at_origin(false, 2, 8);
    const ViewVolumeMaps m = view_volume_maps(s.camera);
    const std::vector<Vec3> corners = view_volume_corners(s.camera);
    for (std::size_t i = 0; i < 8; ++i) {
        const Vec3 c = *warp(m, 1, 1, corners[i]);
        const double depth = i < 4 ? 0.25 : 1;  // near/far
        CHECK(std::abs(c.z + depth) < 1e-15);
        CHECK(std::abs(std::abs(c.x) - depth) < 1e-12);
        CHECK(std::abs(std::abs(c.y) - depth) < 1e-12);
        CHECK(glm::length(*warp(m, 0, 0, corners[i]) - corners[i] / 8.0) < 1e-15);  // the start: eye space at 1/far
    }
}
