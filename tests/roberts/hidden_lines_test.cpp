// SPDX-License-Identifier: MIT
// Roberts' hidden lines against an independent reference: rays sampled along every edge, each cast in world space
// from the point toward the eye and clipped by every other body's planes (Cyrus–Beck), no perspective transform.
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "analysis/line_reference.h"
#include "catch.h"
#include "core/numeric.h"
#include "roberts/hidden_lines.h"

using namespace hsr::algo;

namespace {

// A box of half-sizes h, turned by `angle` about `axis`, centred at c: six quads wound outward.
void add_box(Scene& s, Vec3 c, Vec3 h, double angle, Vec3 axis) {
    const glm::dmat4 turn = glm::rotate(glm::dmat4(1), angle, glm::normalize(axis));
    const auto corner = [&](int i) {
        const Vec3 local((i & 1 ? 1 : -1) * h.x, (i & 2 ? 1 : -1) * h.y, (i & 4 ? 1 : -1) * h.z);
        return c + Vec3(turn * glm::dvec4(local, 0));
    };
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        ScenePolygon p;
        p.id = SceneId(s.polygons.size() + 1);
        for (int k : q) p.vertices.emplace_back(corner(k), 1.0);
        s.polygons.push_back(p);
    }
}

Scene camera_scene(bool orthographic) {
    Scene s;
    s.camera.eye = {0.5, 1.5, 12}, s.camera.target = {0, 0, 0}, s.camera.near = 1, s.camera.far = 40;
    if (orthographic) {
        s.camera.projection = Projection::orthographic;
        s.camera.box[0] = -6, s.camera.box[1] = 6, s.camera.box[2] = -5, s.camera.box[3] = 5;
    }
    return s;
}

Scene random_boxes(std::uint32_t seed, int count, bool orthographic) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-3, 3), size(0.3, 1.4), angle(0, 3.14);
    Scene s = camera_scene(orthographic);
    for (int i = 0; i < count; ++i)
        add_box(s, {pos(rng), pos(rng), pos(rng)}, {size(rng), size(rng), size(rng)}, angle(rng), {pos(rng), pos(rng) + 0.1, pos(rng)});
    return s;
}

hsr::analysis::LineAgreement against_rays(const Scene& s, const LineDrawing& d, int samples) {
    return hsr::analysis::against_rays(s, d, samples);
}

}  // namespace

TEST_CASE("Roberts: every sampled point of every edge is hidden exactly when a ray to the eye passes through a body", "[roberts]") {
    for (const bool orthographic : {false, true})
        for (std::uint32_t seed = 1; seed <= 8; ++seed) {
            const Scene s = random_boxes(seed, 6, orthographic);
            const LineDrawing d = roberts(s).run_to_end();
            INFO((orthographic ? "orthographic" : "perspective") << ", seed " << seed);
            CHECK_FALSE(d.bounded);
            CHECK(d.input.bodies.size() == 6);
            CHECK(d.input.edges.size() == 6 * 12);
            const hsr::analysis::LineAgreement a = against_rays(s, d, 200);
            CHECK(a.wrong == 0);
            CHECK(a.compared > 10 * a.unsure);
        }
}

TEST_CASE("Roberts: back edges are removed, a box behind a larger one is hidden whole, and a piercing edge is hidden inside", "[roberts]") {
    Scene s = camera_scene(false);
    s.camera.eye = {0, 0, 12}, s.camera.target = {0, 0, 0};
    add_box(s, {0, 0, 2}, {2, 2, 0.5}, 0, {0, 1, 0});     // a wide slab in front
    add_box(s, {0, 0, -3}, {0.5, 0.5, 0.5}, 0.3, {1, 1, 0});  // a small cube behind it
    const LineDrawing d = roberts(s).run_to_end();
    std::size_t removed = 0;
    for (std::size_t e = 0; e < d.input.edges.size(); ++e) {
        const BodyEdge& edge = d.input.edges[e];
        removed += d.edges[e].removed;
        if (edge.body == 1 && !d.edges[e].removed) {  // the small cube's drawn edges: all behind the slab
            REQUIRE(d.edges[e].hidden.size() == 1);
            CHECK(d.edges[e].hidden.front().first == Approx(0).margin(1e-12));
            CHECK(d.edges[e].hidden.front().second == Approx(1).margin(1e-12));
        }
        if (edge.body == 0) CHECK(d.edges[e].hidden.empty());  // nothing hides the slab
    }
    CHECK(removed > 0);
    CHECK(removed < d.input.edges.size());
    // the slab seen straight on from the front: its back face's four edges join two back faces only where both face
    // away; the front face's edges are drawn
    // a long thin box through the slab: its part inside the slab is hidden even where no face lies between it and the eye
    Scene pierce = camera_scene(false);
    pierce.camera.eye = {6, 5, 12};
    add_box(pierce, {0, 0, 0}, {2, 2, 0.3}, 0, {0, 1, 0});
    add_box(pierce, {0, 0, 0}, {3.5, 0.2, 0.2}, 0, {0, 1, 0});
    const LineDrawing p = roberts(pierce).run_to_end();
    const hsr::analysis::LineAgreement a = against_rays(pierce, p, 400);
    CHECK(a.wrong == 0);
    bool partly = false;
    for (std::size_t e = 0; e < p.input.edges.size(); ++e)
        if (p.input.edges[e].body == 1 && !p.edges[e].hidden.empty() && p.edges[e].hidden.front().second - p.edges[e].hidden.front().first < 0.99) partly = true;
    CHECK(partly);
}

TEST_CASE("Roberts refuses what it cannot draw, naming the polygon", "[roberts]") {
    Scene open = camera_scene(false);
    add_box(open, {0, 0, 0}, {1, 1, 1}, 0, {0, 1, 0});
    open.polygons.pop_back();  // a box with a missing face
    CHECK_THROWS_AS(convex_bodies(open), InvalidInput);
    CHECK_THROWS_WITH(convex_bodies(open), Catch::Contains("closed"));
    Scene behind = camera_scene(false);
    add_box(behind, {0, 0, 12}, {1, 1, 1}, 0, {0, 1, 0});  // round the eye
    CHECK_THROWS_WITH(convex_bodies(behind), Catch::Contains("behind the eye"));
    // an L of two boxes glued face to face at a shared corner edge is not one convex body: a closed L prism
    Scene l = camera_scene(false);
    const std::vector<glm::dvec2> outline = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    const auto v = [](glm::dvec2 p, double z) { return glm::dvec4(p.x, p.y, z, 1); };
    ScenePolygon bottom, top;
    bottom.id = 1, top.id = 2;
    for (std::size_t i = outline.size(); i-- > 0;) bottom.vertices.push_back(v(outline[i], 0));
    for (const auto& p : outline) top.vertices.push_back(v(p, 1));
    l.polygons = {bottom, top};
    for (std::size_t i = 0; i < outline.size(); ++i) {
        ScenePolygon side;
        side.id = SceneId(3 + i);
        const auto a = outline[i], b = outline[(i + 1) % outline.size()];
        side.vertices = {v(a, 0), v(b, 0), v(b, 1), v(a, 1)};
        l.polygons.push_back(side);
    }
    CHECK_THROWS_WITH(convex_bodies(l), Catch::Contains("not convex"));
}

TEST_CASE("Roberts' step bound ends it with its own event, and every edge is tested against every other body", "[roberts][bound]") {
    const Scene s = random_boxes(3, 5, false);
    std::uint64_t tests = 0, drawn_edges = 0;
    for (const auto& e : roberts(s)) {
        tests += std::holds_alternative<EdgeTested>(e);
        drawn_edges += std::holds_alternative<EdgeFinished>(e);
    }
    CHECK(tests == drawn_edges * 4);  // 5 bodies: each drawn edge against the 4 others
    auto m = roberts(s, {.max_tests = 7});
    RobertsEvent last = BodiesFound{};
    for (const auto& e : m) last = e;
    REQUIRE(std::holds_alternative<RobertsFinished>(last));
    CHECK(std::get<RobertsFinished>(last).bounded);
    CHECK(std::move(m).result().bounded);
}
