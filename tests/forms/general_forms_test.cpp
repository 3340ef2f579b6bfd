// SPDX-License-Identifier: MIT
// The general forms against exact rationals (GMP). The camera stands at the origin looking along +y, so a plan point
// is its own camera-space point and the reference sees the very numbers the machine starts from. For any u of the
// image line the exact reference intersects the projector through u with every segment in rationals and takes the
// nearest hit between the near and far lines; the object-space form's visible parts must give that same primitive
// at every u not within rounding of a boundary, and the image-space form's pixels likewise at every pixel centre.
// The two forms must agree with each other, and count P·(P − 1) comparisons and p·P tests.
#include <cmath>
#include <optional>
#include <random>

#include <gmpxx.h>

#include "catch.h"
#include "core/numeric.h"
#include "forms/general_forms.h"

using namespace hsr::algo;

namespace {

Scene plan(bool orthographic = false, double near = 0.5, double far = 50) {
    Scene s;
    s.camera.eye = {0, 0, 0}, s.camera.target = {0, 1, 0}, s.camera.up = {0, 0, 1};
    s.camera.fov_y = 60, s.camera.near = near, s.camera.far = far;
    if (orthographic) s.camera.projection = Projection::orthographic, s.camera.box[0] = -5, s.camera.box[1] = 5;
    return s;
}
void wall(Scene& s, glm::dvec2 a, glm::dvec2 b) {
    s.segments.push_back({SceneId(s.segments.size() + 1), {}, glm::dvec4(a, 0, 1), glm::dvec4(b, 0, 1)});
}
Scene random_plan(std::uint32_t seed, bool orthographic, int count = 9) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> x(-6, 6), y(-1, 14), len(0.3, 5), angle(0, 6.283185307179586);
    Scene s = plan(orthographic);
    for (int i = 0; i < count; ++i) {
        const glm::dvec2 c(x(rng), y(rng)), d = len(rng) / 2 * glm::dvec2(std::cos(angle(rng)), std::sin(angle(rng)));
        wall(s, c - d, c + d);
    }
    return s;
}

struct Run {
    std::vector<FormsEvent> events;
    FormsResult result;
    std::vector<std::vector<glm::dvec2>> visible;  // per primitive, its visible parts (object space)
};
Run run(const Scene& s, FormsOptions o = {}) {
    Run r;
    r.visible.resize(s.segments.size());
    auto steps = general_forms(s, o);
    for (const auto& e : steps) {
        if (const auto* v = std::get_if<VisiblePartFound>(&e)) r.visible[v->primitive] = v->parts;
        r.events.push_back(e);
    }
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

// The exact nearest segment along the projector through u, and how far (relatively) the runner-up is behind it.
struct Exact {
    std::int32_t nearest = -1;
    double gap = 1;  // (second − first) / first; 1 when there is no second
};
Exact exact_nearest(const Scene& s, const PlanCamera& c, double u) {
    const mpq_class U(u), T(c.tan_half), near(c.near), far(c.far);
    mpq_class ox(0), dx = U * T, dz(1);
    if (!c.perspective) ox = mpq_class(c.left) + (U + 1) / 2 * (mpq_class(c.right_edge) - mpq_class(c.left)), dx = 0;
    std::optional<mpq_class> first, second;
    Exact e;
    for (std::size_t i = 0; i < s.segments.size(); ++i) {
        const mpq_class ax(s.segments[i].a.x), az(s.segments[i].a.y), ex = mpq_class(s.segments[i].b.x) - ax,
            ez = mpq_class(s.segments[i].b.y) - az;
        const mpq_class det = dx * ez - dz * ex;
        if (det == 0) continue;
        const mpq_class wx = ax - ox, wz = az;
        const mpq_class t = (wx * ez - wz * ex) / det, sp = (wx * dz - wz * dx) / det;
        if (sp < 0 || sp > 1 || t < near || t > far) continue;
        if (!first || t < *first) {
            second = first, first = t, e.nearest = std::int32_t(i);
        } else if (!second || t < *second) {
            second = t;
        }
    }
    if (first && second) e.gap = mpq_class((*second - *first) / *first).get_d();
    return e;
}

// The primitive whose visible part holds u, by the object-space form; how near u is to a boundary of any part.
std::int32_t owner(const Run& r, double u, double& nearest_boundary) {
    std::int32_t who = -1;
    nearest_boundary = 1;
    for (std::size_t i = 0; i < r.visible.size(); ++i)
        for (const glm::dvec2 p : r.visible[i]) {
            nearest_boundary = std::min({nearest_boundary, std::abs(u - p.x), std::abs(u - p.y)});
            if (u >= p.x && u < p.y) who = std::int32_t(i);
        }
    return who;
}

// Every u sampled and every pixel centre checked against the exact reference; returns the share of samples left
// out as too close to call (within rounding of a boundary or a tie).
double check_against_exact(const Scene& s, std::uint32_t pixels, std::uint32_t seed) {
    const PlanCamera c = plan_camera(s.camera);
    const Run r = run(s, {.pixels = pixels});
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> any_u(-1, 1);
    int skipped = 0, samples = 2000;
    for (int k = 0; k < samples; ++k) {
        const double u = any_u(rng);
        double boundary = 0;
        const std::int32_t got = owner(r, u, boundary);
        const Exact e = exact_nearest(s, c, u);
        if (boundary < 1e-9 || e.gap < 1e-9) {
            ++skipped;
            continue;
        }
        INFO("u = " << u << ", seed " << seed);
        REQUIRE(got == e.nearest);
    }
    for (std::uint32_t k = 0; k < pixels; ++k) {
        const double u = c.pixel_centre(k, pixels);
        double boundary = 0;
        (void)owner(r, u, boundary);
        const Exact e = exact_nearest(s, c, u);
        if (boundary < 1e-9 || e.gap < 1e-9) continue;
        INFO("pixel " << k << ", seed " << seed);
        REQUIRE(r.result.image_image[k] == e.nearest);
        REQUIRE(r.result.object_image[k] == e.nearest);
    }
    return double(skipped) / samples;
}

}  // namespace

TEST_CASE("general forms: object space's visible parts and image space's pixels against exact rationals", "[forms]") {
    for (const bool orthographic : {false, true})
        for (std::uint32_t seed = 1; seed <= 8; ++seed) {
            const Scene s = random_plan(seed, orthographic);
            CHECK(check_against_exact(s, 64, seed) < 0.01);
        }
}

TEST_CASE("general forms: P·(P − 1) comparisons, p·P tests, object space first, and both images alike", "[forms]") {
    for (std::uint32_t seed = 11; seed <= 16; ++seed) {
        const Scene s = random_plan(seed, seed % 2 == 0, 12);
        const Run r = run(s, {.pixels = 40});
        const auto projected = all_of<PrimitiveProjected>(r);
        const std::uint64_t P = std::uint64_t(std::count_if(projected.begin(), projected.end(), [](const auto& p) { return p.in_view; }));
        const FormsFinished done = all_of<FormsFinished>(r).at(0);
        CHECK(done.in_view == P);
        CHECK(done.comparisons == P * (P - 1));
        CHECK(all_of<PrimitivesCompared>(r).size() == P * (P - 1));
        CHECK(done.tests == 40 * P);
        CHECK(all_of<PixelRendered>(r).size() == 40);
        CHECK(done.differing == 0);
        CHECK(r.result.object_image == r.result.image_image);
        // every object-space event comes before the first image-space one
        std::size_t last_object = 0, first_image = r.events.size();
        for (std::size_t k = 0; k < r.events.size(); ++k) {
            if (std::holds_alternative<PrimitivesCompared>(r.events[k]) || std::holds_alternative<PartRendered>(r.events[k])) last_object = k;
            if (std::holds_alternative<ProjectorTested>(r.events[k])) first_image = std::min(first_image, k);
        }
        CHECK(last_object < first_image);
    }
}

TEST_CASE("general forms: two walls that pierce each other swap at the exact crossing", "[forms]") {
    for (const bool orthographic : {false, true}) {
        Scene s = plan(orthographic);
        wall(s, {1, 4}, {3, 7});
        wall(s, {0.5, 6.5}, {3.5, 4.5});  // crosses the first at (2, 5.5)
        const Run r = run(s, {.pixels = 32});
        const PlanCamera c = plan_camera(s.camera);
        const double crossing = c.image_u({2, 5.5});
        REQUIRE(r.visible[0].size() == 1);
        REQUIRE(r.visible[1].size() >= 1);
        // the first wall is nearer left of the crossing (x < 2 is nearer the eye along it), the second right of it
        CHECK(r.visible[0][0].y == Approx(crossing).epsilon(1e-12));
        CHECK(r.visible[1].back().x == Approx(crossing).epsilon(1e-12));  // its last part starts there
        CHECK(check_against_exact(s, 32, 3) < 0.01);
    }
}

TEST_CASE("general forms: giant next to tiny, near-coplanar stacks, and a wall across the eye's line", "[forms]") {
    SECTION("a wall a million long far away, one a millionth long near") {
        Scene s = plan(false, 1e-3, 1e7);
        wall(s, {-1e6, 1e5}, {1e6, 1e5});
        wall(s, {-1e-6, 2}, {1e-6, 2});
        const Run r = run(s, {.pixels = 33});
        REQUIRE(r.visible[1].size() == 1);  // the tiny wall is seen, over a sliver of the image …
        CHECK(r.visible[1][0].y - r.visible[1][0].x < 2e-6);
        CHECK(r.result.image_image[16] == 1);  // … and it owns the centre pixel, whose projector runs along u = 0
        CHECK(check_against_exact(s, 33, 4) < 0.01);
    }
    SECTION("ten walls stacked 1e-7 apart, all crossing at one point: decided as the exact depths say") {
        Scene s = plan();
        for (int k = 0; k < 10; ++k) wall(s, {-3, 5 + 1e-7 * k}, {3, 5 + 1e-7 * (9 - k)});
        const Run r = run(s, {.pixels = 24});
        CHECK(check_against_exact(s, 24, 5) < 0.1);  // near the common point the walls are within 1e-9 of a tie
    }
    SECTION("ten walls stacked 1e-12 apart: finite parts, and every pixel's winner within rounding of the nearest") {
        Scene s = plan();
        for (int k = 0; k < 10; ++k) wall(s, {-3, 5 + 1e-12 * k}, {3, 5 + 1e-12 * (9 - k)});
        const Run r = run(s, {.pixels = 24});
        for (const auto& parts : r.visible)
            for (const glm::dvec2 p : parts) CHECK((std::isfinite(p.x) && std::isfinite(p.y) && p.y > p.x));
        const PlanCamera c = plan_camera(s.camera);
        for (std::uint32_t k = 0; k < 24; ++k) {
            const Exact e = exact_nearest(s, c, c.pixel_centre(k, 24));
            CHECK(r.result.image_image[k] >= 0);
            CHECK((r.result.image_image[k] == e.nearest || e.gap < 1e-9));
        }
    }
    SECTION("a wall from behind the eye to in front of it is clipped at the near line") {
        Scene s = plan();
        wall(s, {-1, -3}, {1, 6});
        const Run r = run(s, {.pixels = 16});
        const auto p = all_of<PrimitiveProjected>(r).at(0);
        CHECK(p.in_view);
        CHECK(check_against_exact(s, 16, 6) < 0.01);
    }
}

TEST_CASE("general forms: what is not in view, and values near the limits of doubles", "[forms]") {
    Scene s = plan();
    wall(s, {-20, 1}, {-15, 2});                 // outside the field of view
    wall(s, {0, -5}, {0, -1});                   // behind the eye
    wall(s, {0, 2}, {0, 9});                     // edge-on: along the projector u = 0
    wall(s, {-1e300, 10}, {1e300, 10});          // too large: its clipping overflows
    wall(s, {-1e-300, 3}, {1e-300, 3});          // a width the image line cannot hold
    wall(s, {-2, 8}, {2, 8});                    // an ordinary wall
    const Run r = run(s, {.pixels = 16});
    const auto projected = all_of<PrimitiveProjected>(r);
    for (int i = 0; i < 3; ++i) CHECK_FALSE(projected[std::size_t(i)].in_view);
    CHECK(projected[5].in_view);
    for (const auto& e : r.events)
        if (const auto* t = std::get_if<ProjectorTested>(&e)) CHECK(std::isfinite(t->depth));
    for (const auto& parts : r.visible)
        for (const glm::dvec2 p : parts) CHECK((std::isfinite(p.x) && std::isfinite(p.y)));
    const FormsFinished done = all_of<FormsFinished>(r).at(0);
    CHECK_FALSE(done.bounded);
    CHECK(done.differing == 0);
}

TEST_CASE("general forms: a pixel centre exactly on a wall's end is the one place the forms may differ", "[forms]") {
    Scene s = plan();
    wall(s, {-2, 4}, {0, 4});    // ends exactly on the centre line u = 0 (pixel 8's centre of 17)
    wall(s, {-3, 8}, {3, 8});
    const Run r = run(s, {.pixels = 17});
    // object space keeps [from, to): the end at u = 0 belongs to the wall behind; the image-space projector hits the
    // end (s = 1) and takes the nearer wall. Reported, not hidden.
    CHECK(r.result.object_image[8] == 1);
    CHECK(r.result.image_image[8] == 0);
    CHECK(all_of<FormsFinished>(r).at(0).differing == 1);
}

TEST_CASE("general forms: the step bound, and what the machine refuses", "[forms]") {
    const Scene s = random_plan(21, false);
    const Run r = run(s, {.pixels = 16, .max_steps = 5});
    const FormsFinished done = all_of<FormsFinished>(r).at(0);
    CHECK(done.bounded);
    CHECK(done.comparisons + done.tests == 5);

    CHECK_THROWS_AS(run(plan()), InvalidInput);  // no segments
    CHECK_THROWS_AS(run(s, {.pixels = 0}), InvalidInput);
    Scene same = s;
    same.camera.target = same.camera.eye;
    CHECK_THROWS_AS(run(same), InvalidInput);
    Scene wide = s;
    wide.camera.fov_y = 180;
    CHECK_THROWS_AS(run(wide), InvalidInput);
}

TEST_CASE("general forms: subtracting intervals", "[forms]") {
    CHECK(subtract(0, 1, {}) == std::vector<glm::dvec2>{{0, 1}});
    CHECK(subtract(0, 1, {{0.2, 0.4}, {0.3, 0.5}, {0.9, 2}}) == std::vector<glm::dvec2>{{0, 0.2}, {0.5, 0.9}});
    CHECK(subtract(0, 1, {{-1, 2}}).empty());
    CHECK(subtract(0, 1, {{0.5, 0.5}}) == std::vector<glm::dvec2>{{0, 1}});  // an empty interval hides nothing
}
