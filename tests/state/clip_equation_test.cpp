// SPDX-License-Identifier: MIT
// The notes' equation (3), as the clipping panel writes it out: its six forms (and w = ε) put the point on their
// plane, they give the t the machines compute another way (bc(p1) / (bc(p1) − bc(p2)) on the original segment),
// and the view holds the ends it was computed on for exactly the step that computes an intersection.
#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "catch.h"
#include "clipping/clip_scene.h"
#include "clipping/clip_test_helpers.h"
#include "state/clip_view.h"

using namespace hsr::algo;
using hsr::test::random_point;
using hsr::viz::ClipView;
using hsr::viz::initial_view;
using hsr::viz::reduce;

namespace {

double scale_of(const Vec4& a, const Vec4& b) {
    double s = 1;
    for (int i = 0; i < 4; ++i) s = std::max({s, std::fabs(a[i]), std::fabs(b[i])});
    return s;
}

}  // namespace

TEST_CASE("Equation (3) as the notes print it: left and right on a worked segment", "[clipping][equation3]") {
    // p1 = (−2, 0, 0, 1) to p2 = (2, 0, 0, 3): left t = (x1 + w1) / ((x1 − x2) + (w1 − w2)) = −1 / (−4 − 2) = 1/6;
    // right t = (x1 − w1) / ((x1 − x2) + (w2 − w1)) = −3 / (−4 + 2) = 3/2 (the line meets x = w past p2)
    const Vec4 p1{-2, 0, 0, 1}, p2{2, 0, 0, 3};
    const EquationThree left = equation_three(ClipPlane::x_min, ClipSpace::homogeneous, p1, p2);
    CHECK(left.formula == "(x1 + w1) / ((x1 − x2) + (w1 − w2))");
    CHECK(left.numerator == -1);
    CHECK(left.denominator == -6);
    const EquationThree right = equation_three(ClipPlane::x_max, ClipSpace::homogeneous, p1, p2);
    CHECK(right.numerator == -3);
    CHECK(right.denominator == -2);
    CHECK(right.t() == 1.5);
    // in the cube the planes are constants (w = 1): left t = (x1 + 1) / (x1 − x2) = −1 / −4
    const EquationThree cube = equation_three(ClipPlane::x_min, ClipSpace::cube, {-2, 0, 0, 1}, {2, 0, 0, 1});
    CHECK(cube.formula == "(x1 + 1) / (x1 − x2)");
    CHECK(cube.t() == 0.25);
}

TEST_CASE("Every form of equation (3) puts its point on its plane", "[clipping][equation3]") {
    std::mt19937_64 rng(3);
    for (ClipSpace space : {ClipSpace::cube, ClipSpace::homogeneous})
        for (int k = 0; k < plane_count(space); ++k) {
            const ClipPlane r = all_planes[std::size_t(k)];
            int straddling = 0;
            for (int n = 0; n < 2000; ++n) {
                const Vec4 p1 = random_point(rng, space), p2 = random_point(rng, space);
                const double b1 = boundary_value(p1, r, space), b2 = boundary_value(p2, r, space);
                if ((b1 < 0) == (b2 < 0) || std::fabs(b1 - b2) < 1e-3) continue;
                ++straddling;
                const double t = equation_three(r, space, p1, p2).t();
                INFO("plane " << plane_name(r) << ", t = " << t);
                REQUIRE(t >= -1e-12);
                REQUIRE(t <= 1 + 1e-12);
                // a sign wrong anywhere in the form would leave the point off the plane
                CHECK(std::fabs(boundary_value(p1 + t * (p2 - p1), r, space)) <= 1e-9 * scale_of(p1, p2));
            }
            CHECK(straddling > 500);
        }
}

TEST_CASE("The view holds an intersection's ends for its step, and (3) on them gives the machine's t",
          "[clipping][equation3][state]") {
    for (ClipSpace space : {ClipSpace::cube, ClipSpace::homogeneous})
        for (ClipAlgorithm algorithm : {ClipAlgorithm::cohen_sutherland, ClipAlgorithm::sutherland_hodgman}) {
            std::mt19937_64 rng(19);
            ClipJob job;
            job.space = space;
            for (PrimitiveId id = 0; id < 300; ++id) {
                if (algorithm == ClipAlgorithm::cohen_sutherland)
                    job.segments.push_back({id, random_point(rng, space), random_point(rng, space)});
                else
                    job.polygons.push_back({id, {random_point(rng, space), random_point(rng, space), random_point(rng, space)}});
            }
            ClipView view = initial_view(job, algorithm);
            int shown = 0;
            for (const ClipEvent& e : clip_scene(job, algorithm)) {
                reduce(view, e);
                const auto* cut = std::get_if<IntersectionComputed>(&e);
                const auto* edge = std::get_if<EdgeClassified>(&e);
                const bool intersects = cut || (edge && (edge->edge_case == EdgeCase::in_out || edge->edge_case == EdgeCase::out_in));
                REQUIRE(view.intersecting.has_value() == intersects);
                if (!intersects) continue;
                ++shown;
                const auto& [plane, p1, p2] = *view.intersecting;
                const double t = equation_three(plane, space, p1, p2).t();
                const Vec4 at = p1 + t * (p2 - p1);
                const Vec4 machine = cut ? cut->point : edge->intersection;
                INFO(describe(e, space));
                if (cut) CHECK(std::fabs(t - cut->t) <= 1e-9);
                // the machine snaps its point onto the plane; (3)'s point is the same to rounding
                for (int i = 0; i < 4; ++i) CHECK(std::fabs(at[i] - machine[i]) <= 1e-9 * scale_of(p1, p2));
            }
            CHECK(shown > 100);
        }
}
