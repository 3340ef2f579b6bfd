// SPDX-License-Identifier: MIT
// Bounding volumes and their void space; BVH and octree built to their rules; hierarchical frustum culling that is
// conservative (every primitive with a part in the frustum is kept), saves plane tests by inheriting clip flags,
// and detail culling that leaves out only what projects below its threshold.
#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "catch.h"
#include "clipping/sutherland_hodgman.h"
#include "culling/hierarchy.h"
#include "culling/view_frustum.h"
#include "scene/random_scene.h"

using namespace hsr::algo;

namespace {


// A closed box mesh (6 quads, wound outwards) of the given size, rotated about z by `angle`.
std::vector<std::vector<Vec3>> box_mesh(Vec3 half, double angle) {
    const auto r = [&](Vec3 p) { return Vec3(p.x * std::cos(angle) - p.y * std::sin(angle), p.x * std::sin(angle) + p.y * std::cos(angle), p.z); };
    const auto c = [&](int k) { return r({k & 1 ? half.x : -half.x, k & 2 ? half.y : -half.y, k & 4 ? half.z : -half.z}); };
    return {{c(0), c(2), c(3), c(1)}, {c(4), c(5), c(7), c(6)}, {c(0), c(1), c(5), c(4)},
            {c(2), c(6), c(7), c(3)}, {c(0), c(4), c(6), c(2)}, {c(1), c(3), c(7), c(5)}};
}

std::vector<Vec3> points_of(const std::vector<std::vector<Vec3>>& mesh) {
    std::vector<Vec3> p;
    for (const auto& f : mesh) p.insert(p.end(), f.begin(), f.end());
    return p;
}

bool inside_frustum_somewhere(const Scene& s, const ScenePolygon& p) {
    ClipPolygon clip{p.id, {}};
    for (const auto& v : p.vertices) clip.vertices.push_back(to_clip(s, v));
    return sutherland_hodgman(std::move(clip), {.space = ClipSpace::homogeneous}).run_to_end().vertices.size() >= 3;
}

}  // namespace

TEST_CASE("void space has a meaning only for a closed solid inside its bounding volume", "[culling][bounds]") {
    CHECK(void_fraction(10, 4).value() == Approx(0.6));
    CHECK_FALSE(void_fraction(10, 0));        // an open surface encloses nothing
    CHECK_FALSE(void_fraction(10, -3));       // wound inwards
    CHECK_FALSE(void_fraction(10, 11));       // more than its bounding volume: not a closed solid inside it
    CHECK_FALSE(void_fraction(0, 0));         // a flat bounding volume
    CHECK(void_fraction(10, 10 * (1 + 1e-12)).value() == 0);  // rounding at a tight fit is no void
}

TEST_CASE("the objects of a polygon soup are its polygons joined through shared vertices", "[culling][bounds]") {
    const auto rod = box_mesh({4, 0.25, 0.25}, 0.6);
    std::vector<std::vector<Vec3>> soup = rod;
    for (auto p : box_mesh({1, 1, 1}, 0)) {  // a second box, apart from the rod
        for (Vec3& v : p) v += Vec3(20, 0, 0);
        soup.push_back(p);
    }
    soup.push_back({Vec3(50, 0, 0), Vec3(51, 0, 0), Vec3(50, 1, 0)});  // a loose triangle
    // and one triangle that touches the rod at one of its corners: it belongs to the rod's object
    soup.push_back({rod[0][0], Vec3(-9, -9, -9), Vec3(-9, -8, -9)});
    const auto objects = connected_objects(soup);
    REQUIRE(objects.size() == 3);
    CHECK(objects[0].size() == rod.size() + 1);
    CHECK(objects[0].back() == soup.size() - 1);
    CHECK(objects[1].size() == 6);  // the second box, whole
    CHECK(objects[1].front() == rod.size());
    CHECK(objects[2] == std::vector<std::size_t>{soup.size() - 2});
    std::vector<std::vector<Vec3>> second;
    for (std::size_t k : objects[1]) second.push_back(soup[k]);
    CHECK(enclosed_volume(second) == Approx(8));  // a closed box of half-extents 1
}

TEST_CASE("bounding volumes enclose their points, and a long rotated rod shows their void space", "[culling][bounds]") {
    const auto rod = box_mesh({4, 0.25, 0.25}, 0.6);  // a thin bar, turned 34° about z
    const std::vector<Vec3> pts = points_of(rod);
    const double volume = enclosed_volume(rod);
    CHECK(volume == Approx(8 * 4 * 0.25 * 0.25));
    const Aabb a = aabb_of(pts);
    const Sphere s = sphere_of(pts);
    const Obb o = obb_of(pts);
    for (const Vec3& p : pts) {
        CHECK(glm::distance(p, s.centre) <= s.radius);
        for (int k = 0; k < 3; ++k) CHECK(std::abs(glm::dot(p - o.centre, o.axes[std::size_t(k)])) <= o.half[k] * (1 + 1e-9) + 1e-12);
    }
    // the OBB finds the rod's own axes: no void; the box and sphere are mostly empty
    CHECK(void_fraction(o.volume(), volume).value() == Approx(0).margin(1e-9));
    CHECK(void_fraction(a.volume(), volume).value() > 0.8);
    CHECK(void_fraction(s.volume(), volume).value() > 0.9);
    CHECK(o.volume() < a.volume());
    CHECK(a.volume() < s.volume());
}

// Each quad of a mesh as two triangles (as an OBJ exporter writes a box), turned by `angle` about `axis` (Rodrigues).
std::vector<std::vector<Vec3>> triangulated_and_turned(const std::vector<std::vector<Vec3>>& quads, Vec3 axis, double angle) {
    const Vec3 k = glm::normalize(axis);
    const auto turn = [&](Vec3 v) { return v * std::cos(angle) + glm::cross(k, v) * std::sin(angle) + k * glm::dot(k, v) * (1 - std::cos(angle)); };
    std::vector<std::vector<Vec3>> out;
    for (const auto& q : quads) {
        out.push_back({turn(q[0]), turn(q[1]), turn(q[2])});
        out.push_back({turn(q[0]), turn(q[2]), turn(q[3])});
    }
    return out;
}

TEST_CASE("the oriented box of a triangulated, turned box is the box itself: no void space", "[culling][bounds][obb]") {
    // a rod, a plate, a crate and a cube (whose principal axes are any three: covariance alone cannot find them)
    for (const Vec3 half : {Vec3(4, 0.25, 0.25), Vec3(2, 1.5, 0.1), Vec3(1.5, 1, 0.7), Vec3(1, 1, 1)})
        for (const auto& [axis, angle] : std::vector<std::pair<Vec3, double>>{{{0, 0, 1}, 0.6}, {{1, 2, 3}, 0.6}, {{-2, 1, 0.5}, 1.1}, {{0, 1, 0}, 0.0}}) {
            const auto box = triangulated_and_turned(box_mesh(half, 0), axis, angle);
            const std::vector<Vec3> pts = points_of(box);
            const double volume = enclosed_volume(box);
            INFO("half " << half.x << " " << half.y << " " << half.z << ", turned " << angle << " about " << axis.x << " " << axis.y << " " << axis.z);
            REQUIRE(volume == Approx(8 * half.x * half.y * half.z));
            const Obb o = obb_of(pts, face_normals(box));
            for (const Vec3& p : pts)
                for (int k = 0; k < 3; ++k) CHECK(std::abs(glm::dot(p - o.centre, o.axes[std::size_t(k)])) <= o.half[k] * (1 + 1e-9) + 1e-12);
            CHECK(void_fraction(o.volume(), volume).value() < 0.01);
            // from the points alone (principal axes of the distinct corners) a box with three different sides is found too
            if (half.x != half.y && half.y != half.z) CHECK(void_fraction(obb_of(pts).volume(), volume).value() < 0.01);
        }
}

TEST_CASE("a BVH holds every primitive in one leaf, each box holding what is below it", "[culling][bvh]") {
    const Scene s = random_triangles({.count = 500, .seed = 3, .size = 0.5});
    const Hierarchy h = build_hierarchy(polygon_boxes(s), {.kind = HierarchyKind::bvh, .max_primitives = 4}).run_to_end();
    std::vector<int> seen(h.boxes.size(), 0);
    for (const auto& n : h.nodes) {
        for (std::uint32_t p : n.primitives) {
            ++seen[p];
            CHECK(n.box.contains(h.boxes[p]));
        }
        for (std::uint32_t c : n.children) CHECK(n.box.contains(h.nodes[c].box));
        if (n.children.empty()) CHECK(n.primitives.size() <= 4);
        else CHECK(n.primitives.empty());
    }
    CHECK(std::all_of(seen.begin(), seen.end(), [](int k) { return k == 1; }));
    CHECK(h.depth <= 12);  // median splits: about log2(500 / 4) + 1
}

TEST_CASE("an octree splits a cell in eight until few primitives or the smallest cell, keeping straddlers", "[culling][octree]") {
    const Scene s = random_triangles({.count = 500, .seed = 3, .size = 0.5});
    const Hierarchy h = build_hierarchy(polygon_boxes(s), {.kind = HierarchyKind::octree, .max_primitives = 8}).run_to_end();
    std::size_t held = 0;
    for (const auto& n : h.nodes) {
        held += n.primitives.size();
        for (std::uint32_t p : n.primitives) CHECK(n.box.contains(h.boxes[p]));
        for (std::uint32_t c : n.children) {
            CHECK(n.box.contains(h.nodes[c].box));
            CHECK(h.nodes[c].box.size().x == Approx(n.box.size().x / 2));
        }
    }
    CHECK(held == h.boxes.size());
    SECTION("the smallest cell stops the split even with many primitives") {
        std::vector<Aabb> same(50, Aabb{Vec3(0.1), Vec3(0.2)});
        same.push_back({Vec3(-8), Vec3(-7.9)});
        auto m = build_hierarchy(same, {.kind = HierarchyKind::octree, .max_primitives = 4, .min_cell = 2});
        bool by_cell = false;
        for (const auto& e : m)
            if (const auto* b = std::get_if<HierarchyNodeBuilt>(&e)) by_cell |= b->leaf == LeafReason::cell_size;
        CHECK(by_cell);
    }
}

TEST_CASE("hierarchical frustum culling is conservative and inherits clip flags", "[culling][frustum]") {
    const HierarchyKind kind = GENERATE(HierarchyKind::bvh, HierarchyKind::octree);
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(-6, 6);
    int trials_leaving_out = 0;
    for (int trial = 0; trial < 8; ++trial) {
        Scene s = random_triangles({.count = 800, .seed = std::uint32_t(trial + 1), .size = 0.4});
        s.camera.eye = {u(rng), u(rng) / 2, u(rng) + 8};
        s.camera.target = {u(rng) / 3, 0, u(rng) / 3};
        s.camera.fov_y = 40;
        const Hierarchy h = build_hierarchy(polygon_boxes(s), {.kind = kind}).run_to_end();
        const HierarchyCull c = cull_hierarchy(&h, s.camera).run_to_end();
        const std::vector<Plane> f = view_frustum(s.camera);
        int missed = 0, kept = 0, unlike_own_box = 0;
        for (std::size_t i = 0; i < s.polygons.size(); ++i) {
            missed += inside_frustum_somewhere(s, s.polygons[i]) && !c.kept[i];
            kept += c.kept[i];
            // the hierarchy keeps exactly the primitives whose own boxes pass all six planes: the nodes and the
            // inherited clip flags only save tests, never change an answer
            const bool own_box_in = std::all_of(f.begin(), f.end(), [&](const Plane& p) { return box_side(h.boxes[i], p) >= 0; });
            unlike_own_box += own_box_in != bool(c.kept[i]);
        }
        INFO("trial " << trial);
        CHECK(missed == 0);
        CHECK(unlike_own_box == 0);
        CHECK(kept + int(c.outside) == int(s.polygons.size()));
        CHECK(c.plane_tests < 6 * std::uint32_t(s.polygons.size()));  // fewer tests than every box against six planes
        trials_leaving_out += kept < int(s.polygons.size());
    }
    CHECK(trials_leaving_out >= 4);
}

TEST_CASE("detail culling leaves out only nodes below its threshold, and nothing at threshold 0", "[culling][detail]") {
    Scene s = random_triangles({.count = 800, .seed = 9, .size = 0.3, .far = 60});
    s.camera.eye = {0, 0, 30};
    const Hierarchy h = build_hierarchy(polygon_boxes(s), {.kind = HierarchyKind::octree}).run_to_end();
    auto m = cull_hierarchy(&h, s.camera, {.detail_pixels = 40, .viewport_height = 480});
    int small = 0;
    for (const auto& e : m)
        if (const auto* n = std::get_if<NodeCulled>(&e); n && n->outcome == NodeOutcome::too_small) {
            ++small;
            CHECK(n->pixels < 40);
            CHECK(projected_pixels(h.nodes[n->node].box, s.camera, 480) < 40);
        }
    CHECK(small > 0);
    CHECK(m.result().too_small > 0);
    const HierarchyCull none = cull_hierarchy(&h, s.camera, {.detail_pixels = 0}).run_to_end();
    CHECK(none.too_small == 0);
}

TEST_CASE("a camera inside a box and a box straddling the near plane are never rejected", "[culling][frustum][extremes]") {
    Camera c{.eye = {0, 0, 0}, .target = {0, 0, -1}, .near = 1, .far = 10};
    const std::vector<Plane> f = view_frustum(c);
    const Aabb around_eye{Vec3(-1), Vec3(1)}, across_near{Vec3(-0.5, -0.5, -1.5), Vec3(0.5, 0.5, -0.5)};
    for (const Aabb& b : {around_eye, across_near})
        for (const Plane& p : f) CHECK(box_side(b, p) >= 0);
    CHECK(std::isinf(projected_pixels(around_eye, c, 480)));
}
