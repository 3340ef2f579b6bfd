// SPDX-License-Identifier: MIT
// The differential test without a window: every generated family, every hidden-surface algorithm and setting,
// against the ray cast with no acceleration; every differing pixel must be an edge or a depth tie. (tests/gui's
// `differential` adds OpenGL as a second reference.)
#include "catch.h"

#include <algorithm>
#include <map>
#include <string>

#include "depth_sort/depth_sort.h"
#include "renderers.h"
#include "scene_families.h"
#include "zbuffer/zbuffer_fill.h"

using namespace hsr;

namespace {

test::Tally against_ray_cast(const algo::Scene& scene, const test::Renderer& r, algo::Viewport vp, test::Drawn* drawn = nullptr) {
    const test::Drawn reference = test::ray_cast(scene, vp);
    const test::Drawn d = r.draw(scene, vp);
    CHECK_FALSE(d.bounded);
    const algo::ZBufferOptions zo = algo::zbuffer_options(scene, vp, algo::DepthFormat::int24);
    const test::TieRule tie{r.formats.empty() ? std::vector{algo::DepthFormat::int24} : r.formats, zo.range, zo.perspective};
    std::vector<std::string> first;
    const test::Tally t = test::compare_images(d.ids, reference.ids, vp, test::scene_outlines(scene, vp), d.parts, tie, &first, 3);
    for (const std::string& pixel : first) UNSCOPED_INFO("unexplained pixel " << pixel);
    if (drawn) *drawn = d;
    return t;
}

}  // namespace

TEST_CASE("every family, every algorithm: each pixel that differs from the ray cast is an edge or a depth tie", "[differential]") {
    const algo::Viewport vp{64, 48};
    for (const test::SceneFamily& family : test::scene_families())
        for (std::uint32_t seed = 1; seed <= 2; ++seed) {
            const algo::Scene scene = family.make(seed, 4.0 / 3);
            for (const test::Renderer& r : test::cpu_renderers()) {
                INFO(family.name << " seed " << seed << " by " << r.name);
                const test::Tally t = against_ray_cast(scene, r, vp);
                CHECK(t.compared == 64 * 48);
                CHECK(t.unexplained == 0);
            }
        }
}

TEST_CASE("the classes are not vacuous: a polygon missing from an image is unexplained", "[differential]") {
    const algo::Viewport vp{64, 48};
    algo::Scene scene = test::scene_families().back().make(1, 4.0 / 3);  // random triangles
    const test::Drawn whole = test::ray_cast(scene, vp);
    // the polygon seen at the most pixels goes
    std::map<algo::SceneId, int> pixels;
    for (const algo::SceneId id : whole.ids) ++pixels[id];
    pixels.erase(0);
    REQUIRE_FALSE(pixels.empty());
    const algo::SceneId gone = std::max_element(pixels.begin(), pixels.end(), [](const auto& a, const auto& b) { return a.second < b.second; })->first;
    std::erase_if(scene.polygons, [&](const algo::ScenePolygon& p) { return p.id == gone; });
    const test::Drawn without = test::ray_cast(scene, vp);
    const algo::Scene full = test::scene_families().back().make(1, 4.0 / 3);
    const algo::ZBufferOptions zo = algo::zbuffer_options(full, vp, algo::DepthFormat::int24);
    const test::Tally t = test::compare_images(without.ids, whole.ids, vp, test::scene_outlines(full, vp), {},
                                               {{algo::DepthFormat::int24}, zo.range, zo.perspective});
    CHECK(t.differ > 0);
    CHECK(t.unexplained > 0);
    CHECK(t.unexplained + t.edge + t.tie == t.differ);
}

TEST_CASE("depth sort: a cycle of five no plane of theirs cuts is cut across, and painted right", "[differential][depth_sort]") {
    // Found by the differential test (cyclic bars, seed 4): the pairs of a five-member cycle are each ordered by a
    // plane test, yet no member's plane cuts another. The sort used to give up and draw R first (the list's order):
    // 16 pixels at 192×144 of a bar painted over the one in front of it. Since the sort splits R by Q's plane, as
    // the notes do (it split Q by R's), seed 4 breaks its cycles by the planes; seed 482 is one of the 10 seeds in
    // 1,500 that still meets a cycle no plane of its members cuts.
    const algo::Viewport vp{192, 144};
    const auto& families = test::scene_families();
    const auto cyclic = std::find_if(families.begin(), families.end(), [](const auto& f) { return f.name == "cyclic"; });
    REQUIRE(cyclic != families.end());
    const auto renderers = test::cpu_renderers();
    const auto depth_sort = std::find_if(renderers.begin(), renderers.end(), [](const auto& r) { return r.name == "depth-sort"; });
    REQUIRE(depth_sort != renderers.end());
    for (const std::uint32_t seed : {4u, 482u}) {
        INFO("seed " << seed);
        const algo::Scene scene = cyclic->make(seed, 4.0 / 3);
        const test::Tally t = against_ray_cast(scene, *depth_sort, vp);
        CHECK(t.unexplained == 0);
        // and the machine says how it broke the cycle
        auto machine = algo::depth_sort(algo::sort_polygons(scene));
        int across = 0;
        for (const auto& e : machine)
            if (const auto* cut = std::get_if<algo::PolygonCut>(&e)) across += cut->across;
        if (seed == 482) CHECK(across >= 1);
    }
}

TEST_CASE("occlusion culling: orthographic cameras and occluders reaching behind the eye hide nothing visible",
          "[differential][culling]") {
    // Found by the differential test. The occlusion frustum was built through the eye point for an orthographic
    // camera too (orthographic seed 4: polygon 4 culled where it is the nearest), and from polygons
    // reaching in front of the near plane, behind the eye, whose frustum through the eye turns inside out
    // (behind-eye seed 20: polygon 17 culled).
    const algo::Viewport vp{192, 144};
    const auto renderers = test::cpu_renderers();
    const auto culled = std::find_if(renderers.begin(), renderers.end(), [](const auto& r) { return r.name.starts_with("culling"); });
    REQUIRE(culled != renderers.end());
    for (const auto& [family_name, family_seed] : {std::pair{"orthographic", 4u}, std::pair{"behind-eye", 20u}}) {
        // Copies, not the bindings themselves: clang 14 cannot capture a structured binding in a lambda.
        const std::string name = family_name;
        const unsigned seed = family_seed;
        INFO(name << " seed " << seed);
        const auto& families = test::scene_families();
        const auto family = std::find_if(families.begin(), families.end(), [&](const auto& f) { return f.name == name; });
        REQUIRE(family != families.end());
        const test::Tally t = against_ray_cast(family->make(seed, 4.0 / 3), *culled, vp);
        CHECK(t.unexplained == 0);
    }
}
