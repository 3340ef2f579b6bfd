// SPDX-License-Identifier: MIT
// Coorg and Teller's occluder rank on its own, f = −A (n̂ · v̂) / |v|², against an independent reference: the solid
// angle a triangle subtends at the eye (Van Oosterom and Strackee's formula), which the rank approximates for a
// polygon small against its distance. Its laws: zero when a polygon faces away or is seen edge-on, a quarter at twice
// the distance, unchanged when polygon and distance grow together, and under an orthographic camera the area the
// polygon covers on the screen, whatever its distance.
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "catch.h"
#include "culling/occluders.h"

using namespace hsr::algo;

namespace {

// The solid angle of the triangle abc seen from the origin.
double solid_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double numerator = std::abs(glm::dot(a, glm::cross(b, c)));
    const double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    return 2 * std::atan2(numerator, denominator);
}

// A triangle of edge about `size` at `centre`, turned by `turn`, wound to face the origin.
std::vector<Vec3> facing_triangle(const Vec3& centre, double size, const glm::dmat3& turn) {
    std::vector<Vec3> t = {centre + turn * Vec3(-size / 2, -size / 3, 0), centre + turn * Vec3(size / 2, -size / 3, 0),
                           centre + turn * Vec3(0, size * 2 / 3, 0)};
    const Vec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
    if (glm::dot(n, centre) > 0) std::swap(t[1], t[2]);  // the front (counter-clockwise) side toward the eye
    return t;
}

}  // namespace

TEST_CASE("the occluder rank approximates the solid angle and orders small occluders as it does", "[culling][occluders]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1), far(20, 60), size(0.05, 0.5), angle(0, 1.2);
    std::vector<std::pair<double, double>> ranked;  // (rank, solid angle)
    for (int i = 0; i < 300; ++i) {
        const Vec3 centre = glm::normalize(Vec3(u(rng), u(rng), -2)) * far(rng);
        const glm::dmat3 turn(glm::rotate(glm::dmat4(1), angle(rng), glm::normalize(Vec3(u(rng), u(rng), 1))));
        const std::vector<Vec3> t = facing_triangle(centre, size(rng), turn);
        const double rank = occluder_rank(t, Vec3(0)), omega = solid_angle(t[0], t[1], t[2]);
        REQUIRE(rank > 0);
        CHECK(rank == Approx(omega).epsilon(1e-3));  // small against the distance: the two agree closely
        ranked.emplace_back(rank, omega);
    }
    // ranked by f, the occluders come in the solid angle's order but where two are within the approximation's error
    std::sort(ranked.begin(), ranked.end());
    for (std::size_t k = 1; k < ranked.size(); ++k) CHECK(ranked[k].second >= ranked[k - 1].second * (1 - 2e-3));
}

TEST_CASE("the occluder rank's laws: facing away, edge-on, distance and scale, orthographic", "[culling][occluders]") {
    const glm::dmat3 turn(glm::rotate(glm::dmat4(1), 0.4, glm::normalize(Vec3(1, 2, 3))));
    const std::vector<Vec3> t = facing_triangle(Vec3(1, 2, -10), 1.5, turn);
    const double f = occluder_rank(t, Vec3(0));
    REQUIRE(f > 0);
    CHECK(occluder_rank({t[0], t[2], t[1]}, Vec3(0)) == 0);  // the same triangle facing away
    const std::vector<Vec3> edge_on = {Vec3(0, -1, -10), Vec3(0, 1, -10), Vec3(0, 0, -12)};  // in a plane through the eye
    CHECK(occluder_rank(edge_on, Vec3(0)) == Approx(0).margin(1e-15));
    std::vector<Vec3> twice_as_far, twice_as_large;
    for (const Vec3& p : t) twice_as_far.push_back(p + Vec3(1, 2, -10)), twice_as_large.push_back(2.0 * p);
    CHECK(occluder_rank(twice_as_far, Vec3(0)) == Approx(f / 4).epsilon(1e-12));  // the centroid moved to twice the distance
    CHECK(occluder_rank(twice_as_large, Vec3(0)) == Approx(f).epsilon(1e-12));    // area ×4, distance² ×4
    // orthographic, looking down −z: the area the triangle covers on the screen, from any distance
    Camera ortho;
    ortho.projection = Projection::orthographic, ortho.eye = {0, 0, 5}, ortho.target = {0, 0, 0};
    const std::vector<Vec3> flat = {Vec3(0, 0, -3), Vec3(2, 0, -3), Vec3(0, 3, -3)};  // area 3, facing +z
    CHECK(occluder_rank(flat, ortho) == Approx(3).epsilon(1e-12));
    std::vector<Vec3> deeper;
    for (const Vec3& p : flat) deeper.push_back(p + Vec3(0, 0, -40));
    CHECK(occluder_rank(deeper, ortho) == Approx(3).epsilon(1e-12));
}
