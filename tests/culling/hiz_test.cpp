// SPDX-License-Identifier: MIT
// The hierarchical z-buffer: every pyramid texel is the farthest of those below it, for sizes that are not powers of
// two; isOccluded answers as a test of every pixel under the footprint would; Cull_or_Render over an octree gives
// the z-buffer's image exactly while leaving out what a wall hides; boxes reaching the eye are never occluded.
#include <algorithm>
#include <random>

#include "catch.h"
#include "culling/hiz.h"
#include "scene/random_scene.h"

using namespace hsr::algo;

namespace {


// Random triangles behind a wall that fills the view, the wall listed last.
Scene behind_a_wall(std::size_t count) {
    Scene s = random_triangles({.count = count, .seed = 21, .size = 0.4, .far = 40});
    s.camera.eye = {0, 0, 14};
    for (auto& p : s.polygons)
        for (auto& v : p.vertices) v.z -= 6;  // all at z in [-10.4, -1.6]
    s.polygons.push_back({60000, {120, 120, 120}, {{-30, -30, 1, 1}, {30, -30, 1, 1}, {30, 30, 1, 1}, {-30, 30, 1, 1}}});
    return s;
}

}  // namespace

TEST_CASE("each pyramid texel holds the farthest depth below it, at any size", "[culling][hiz]") {
    const auto [w, h] = GENERATE(std::pair{7, 5}, std::pair{1023, 767}, std::pair{1, 1}, std::pair{2, 9});
    std::mt19937 rng(std::uint32_t(w * 31 + h));
    std::uniform_int_distribution<std::uint32_t> code(0, 1000);
    std::vector<std::uint32_t> depth(std::size_t(w) * std::size_t(h));
    for (auto& d : depth) d = code(rng);
    const ZPyramid z(depth, w, h);
    CHECK(z.width(z.levels() - 1) == 1);
    CHECK(z.height(z.levels() - 1) == 1);
    CHECK(z.at(z.levels() - 1, 0, 0) == *std::max_element(depth.begin(), depth.end()));
    for (std::size_t l = 1; l < z.levels(); ++l)
        for (int y = 0; y < z.height(l); ++y)
            for (int x = 0; x < z.width(l); ++x) {
                std::uint32_t farthest = 0;
                for (int cy = 2 * y; cy < std::min(2 * y + 2, z.height(l - 1)); ++cy)
                    for (int cx = 2 * x; cx < std::min(2 * x + 2, z.width(l - 1)); ++cx) farthest = std::max(farthest, z.at(l - 1, cx, cy));
                REQUIRE(z.at(l, x, y) == farthest);
            }
    SECTION("isOccluded agrees with testing every pixel under the footprint") {
        std::uniform_int_distribution<int> px(-2, w + 2), py(-2, h + 2);
        for (int k = 0; k < 300; ++k) {
            int x0 = px(rng), x1 = px(rng), y0 = py(rng), y1 = py(rng);
            if (x1 < x0) std::swap(x0, x1);
            if (y1 < y0) std::swap(y0, y1);
            const std::uint32_t near = code(rng) / 2 + 500;
            bool all_nearer = true;
            for (int y = std::max(y0, 0); y < std::min(y1, h); ++y)
                for (int x = std::max(x0, 0); x < std::min(x1, w); ++x) all_nearer &= depth[std::size_t(y) * std::size_t(w) + std::size_t(x)] < near;
            INFO("footprint [" << x0 << ", " << x1 << ") × [" << y0 << ", " << y1 << "), near " << near);
            REQUIRE(z.occluded({x0, y0, x1, y1}, near) == all_nearer);
        }
    }
}

TEST_CASE("Cull_or_Render gives the z-buffer's image and leaves out what a wall hides", "[culling][hiz]") {
    const Viewport vp = GENERATE(Viewport{64, 48}, Viewport{7, 5}, Viewport{1, 1});
    const Scene s = behind_a_wall(600);
    const Hierarchy h = build_hierarchy(polygon_boxes(s), {.kind = HierarchyKind::octree, .max_primitives = 4}).run_to_end();
    const ZBufferOptions o = zbuffer_options(s, vp, DepthFormat::int24, EventDetail::polygon);
    const HizResult hiz = hiz_render(&s, &h, o).run_to_end();
    const FrameDepth all = zbuffer_fill(project_polygons(s, vp), o).run_to_end();
    CHECK(hiz.buffers.image.ids == all.image.ids);
    CHECK(hiz.buffers.depth == all.depth);
    const auto rendered = std::count(hiz.rendered.begin(), hiz.rendered.end(), 1);
    INFO(rendered << " of " << s.polygons.size() << " rendered");
    CHECK(hiz.occluded_nodes > 0);
    CHECK(rendered < std::int64_t(s.polygons.size()) / 4);
}

TEST_CASE("Cull_or_Render on random scenes equals the z-buffer", "[culling][hiz]") {
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
        const Scene s = random_triangles({.count = 400, .seed = seed, .size = 1.0});
        const Hierarchy h = build_hierarchy(polygon_boxes(s), {.kind = seed % 2 ? HierarchyKind::octree : HierarchyKind::bvh}).run_to_end();
        const ZBufferOptions o = zbuffer_options(s, {80, 60}, DepthFormat::int24, EventDetail::polygon);
        const HizResult hiz = hiz_render(&s, &h, o).run_to_end();
        const FrameDepth all = zbuffer_fill(project_polygons(s, {80, 60}), o).run_to_end();
        INFO("seed " << seed);
        CHECK(hiz.buffers.depth == all.depth);
    }
}

TEST_CASE("a box reaching behind the near plane, or round the eye, is never occluded", "[culling][hiz][extremes]") {
    Scene s;
    s.camera = {.eye = {0, 0, 5}, .target = {0, 0, 0}, .near = 1, .far = 20};
    const ZBufferOptions o = zbuffer_options(s, {32, 24}, DepthFormat::int24, EventDetail::polygon);
    for (const Aabb& b : {Aabb{Vec3(-1, -1, 3.5), Vec3(1, 1, 4.5)}, Aabb{Vec3(-1, -1, 4), Vec3(1, 1, 6)}}) {
        const BoxOnScreen on = box_on_screen(b, s, o);
        CHECK(on.reaches_eye);
        CHECK(on.footprint.x1 - on.footprint.x0 == 32);
    }
    const BoxOnScreen far = box_on_screen({Vec3(-1), Vec3(1)}, s, o);
    CHECK_FALSE(far.reaches_eye);
}
