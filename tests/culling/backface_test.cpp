// SPDX-License-Identifier: MIT
// Back-face culling: the three forms agree on closed meshes; a constant look direction is wrong at the edge of a
// wide field of view.
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "catch.h"
#include "core/numeric.h"
#include "culling/backface.h"
#include "state/backface_session.h"

using namespace hsr::algo;

namespace {

// Closed meshes, faces counter-clockwise seen from outside.
std::vector<Face> cube(Vec3 c, double h) {
    const auto v = [&](int x, int y, int z) { return c + h * Vec3(x, y, z); };
    return {{1, {v(-1, -1, 1), v(1, -1, 1), v(1, 1, 1), v(-1, 1, 1)}},      {2, {v(1, -1, -1), v(-1, -1, -1), v(-1, 1, -1), v(1, 1, -1)}},
            {3, {v(1, -1, 1), v(1, -1, -1), v(1, 1, -1), v(1, 1, 1)}},      {4, {v(-1, -1, -1), v(-1, -1, 1), v(-1, 1, 1), v(-1, 1, -1)}},
            {5, {v(-1, 1, 1), v(1, 1, 1), v(1, 1, -1), v(-1, 1, -1)}},      {6, {v(-1, -1, -1), v(1, -1, -1), v(1, -1, 1), v(-1, -1, 1)}}};
}
std::vector<Face> octahedron(Vec3 c, double r) {
    const Vec3 px = c + Vec3(r, 0, 0), nx = c - Vec3(r, 0, 0), py = c + Vec3(0, r, 0), ny = c - Vec3(0, r, 0),
               pz = c + Vec3(0, 0, r), nz = c - Vec3(0, 0, r);
    return {{11, {px, py, pz}}, {12, {py, nx, pz}}, {13, {nx, ny, pz}}, {14, {ny, px, pz}},
            {15, {py, px, nz}}, {16, {nx, py, nz}}, {17, {ny, nx, nz}}, {18, {px, ny, nz}}};
}

std::vector<FaceTested> run(const std::vector<Face>& faces, const Camera& c, BackfaceTest t) {
    std::vector<FaceTested> out;
    for (const auto& e : cull_back_faces(faces, c, t))
        if (const auto* f = std::get_if<FaceTested>(&e)) out.push_back(*f);
    return out;
}

}  // namespace

TEST_CASE("the three back-face tests agree on closed meshes seen from outside", "[culling][backface]") {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> dir(-1, 1), dist(4, 12);
    std::vector<Face> meshes = cube(Vec3(0), 1);
    for (const Face& f : octahedron(Vec3(3, 0.5, -1), 1.2)) meshes.push_back(f);
    int compared = 0;
    for (int n = 0; n < 500; ++n) {
        Vec3 d(dir(rng), dir(rng), dir(rng));
        if (glm::length(d) < 0.1) continue;
        Camera c;
        c.target = Vec3(1.5, 0.2, -0.5);
        c.eye = c.target + glm::normalize(d) * dist(rng);
        c.fov_y = 75;
        c.near = 0.1;
        c.far = 100;
        const auto vv = run(meshes, c, BackfaceTest::view_vector);
        const auto pe = run(meshes, c, BackfaceTest::plane_equation);
        const auto sw = run(meshes, c, BackfaceTest::screen_winding);
        for (std::size_t i = 0; i < meshes.size(); ++i) {
            if (std::fabs(pe[i].value) < 1e-9) continue;  // edge-on: each test may round it either way
            INFO("eye " << c.eye.x << ", " << c.eye.y << ", " << c.eye.z << " face " << meshes[i].id);
            CHECK(vv[i].facing == pe[i].facing);
            if (sw[i].facing != Facing::outside_view) CHECK(sw[i].facing == pe[i].facing);
            ++compared;
        }
    }
    CHECK(compared > 5000);
}

TEST_CASE("about half the faces of a closed mesh are culled", "[culling][backface]") {
    Camera c;
    c.eye = Vec3(5, 4, 6);
    const auto kept = cull_back_faces(cube(Vec3(0), 1), c, BackfaceTest::view_vector).run_to_end();
    CHECK(kept.size() == 3);  // a cube seen from a corner direction shows three faces
}

TEST_CASE("a constant look direction is wrong at the edge of a wide field of view, the view vector is not",
          "[culling][backface]") {
    Camera c;  // at the origin, looking down −z, 120° field of view
    c.eye = Vec3(0);
    c.target = Vec3(0, 0, -1);
    c.fov_y = 120;
    c.near = 0.1;
    c.far = 100;
    // a polygon 59° to the left of the view axis, its normal turned toward the eye but slightly away from −z
    const Vec3 centre(-5, 0, -3), n = glm::normalize(Vec3(1, 0, -0.2));
    const Vec3 u = glm::normalize(glm::cross(n, Vec3(0, 1, 0))), w = glm::cross(n, u);
    const Face face{1, {centre - u - w, centre + u - w, centre + u + w, centre - u + w}};
    Plane p;
    REQUIRE(plane_of(face.vertices, p));
    REQUIRE(glm::dot(p.n, n) > 0.999);  // wound counter-clockwise around n

    const double constant_direction = glm::dot(Vec3(0, 0, -1), p.n);  // the look direction instead of v
    CHECK(constant_direction > 0);                                    // …would call it a back face
    for (auto t : {BackfaceTest::view_vector, BackfaceTest::plane_equation, BackfaceTest::screen_winding}) {
        INFO(to_string(t));
        CHECK(run({face}, c, t).front().facing == Facing::front);  // …but the eye sees its front
    }
}

TEST_CASE("back-face culling refuses degenerate and NaN faces by name", "[culling][backface][input]") {
    Camera c;
    CHECK_THROWS_WITH(cull_back_faces({{4, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}}}, c, BackfaceTest::view_vector),
                      "face 4 is degenerate (it has no area)");
    CHECK_THROWS_WITH(cull_back_faces({{5, {{0, 0, 0}, {1, 0, 0}}}}, c, BackfaceTest::view_vector),
                      "face 5 has fewer than 3 vertices");
    CHECK_THROWS_AS(cull_back_faces({{6, {{0, 0, 0}, {1, 0, std::nan("")}, {0, 1, 0}}}}, c, BackfaceTest::view_vector),
                    InvalidInput);
    for (const auto& e : cull_back_faces(cube(Vec3(0), 1), c, BackfaceTest::screen_winding))
        CHECK_FALSE(describe(e).empty());
}

TEST_CASE("the back-face lesson's view folds to the faces the machine keeps", "[culling][backface][state]") {
    for (const char* id : {"backface_view_vector", "backface_plane_equation", "backface_screen_winding"}) {
        INFO(id);
        hsr::viz::BackfaceSession session(hsr::viz::load_lesson(hsr::viz::data_dir() + "/lessons/06_backface.toml", id));
        session.seek_end();
        const auto kept = cull_back_faces(faces_of(session.lesson().scene), session.lesson().scene.camera,
                                          machine_of<BackfaceTest>(session.lesson()))
                              .run_to_end();
        std::vector<std::int32_t> shown;
        for (const auto& f : session.view().faces)
            if (f.facing == Facing::front) shown.push_back(f.id);
        CHECK(shown == kept);
        CHECK(session.view().kept + session.view().culled == int(session.view().faces.size()));
        session.seek(3);
        CHECK(session.current_line() >= 3);
        CHECK_FALSE(session.narration().empty());
    }
}
