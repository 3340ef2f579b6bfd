// SPDX-License-Identifier: MIT
// The scan-line algorithm gives the z-buffer's image, pixel for pixel, and tells its edge table as it goes.
#include <map>

#include "catch.h"
#include "scene/random_scene.h"
#include "zbuffer/scanline.h"

using namespace hsr::algo;

TEST_CASE("the scan-line algorithm gives the same image as the z-buffer on random scenes", "[scanline][zbuffer]") {
    const auto [format, size] = GENERATE(table<DepthFormat, double>({{DepthFormat::int24, 1.5},
                                                                      {DepthFormat::int16, 3.0},
                                                                      {DepthFormat::float32, 0.3}}));
    for (std::uint32_t seed = 1; seed <= 3; ++seed) {
        const Scene s = random_triangles({.count = 100, .seed = seed, .size = size, .near = 0.5, .far = 50});
        const Viewport vp{97, 61};
        const auto screen = project_polygons(s, vp);
        const FrameDepth z = zbuffer_fill(screen, zbuffer_options(s, vp, format, EventDetail::polygon)).run_to_end();
        const FrameDepth l = scan_line(screen, scan_line_options(s, vp, format)).run_to_end();
        INFO(to_string(format) << ", seed " << seed);
        CHECK(l.polygon == z.polygon);
        CHECK(l.image.rgb == z.image.rgb);
        for (std::size_t k = 0; k < z.depth.size(); ++k)
            if (z.polygon[k] >= 0) REQUIRE(l.depth[k] == z.depth[k]);
    }
}

TEST_CASE("every scan line's active edges come in pairs, one in and one out per polygon", "[scanline]") {
    const Scene s = random_triangles({.count = 30, .seed = 5, .size = 2});
    const Viewport vp{40, 30};
    auto m = scan_line(project_polygons(s, vp), scan_line_options(s, vp, DepthFormat::int24));
    std::map<std::uint32_t, int> flips;  // per polygon on the current line
    int lines = 0;
    std::size_t entered = 0, left = 0;
    for (const auto& e : m) {
        if (std::holds_alternative<ScanLineStarted>(e)) {
            for (const auto& [p, n] : flips) REQUIRE(n % 2 == 0);
            flips.clear();
            ++lines;
        }
        if (const auto* c = std::get_if<EdgeCrossed>(&e)) ++flips[c->polygon];
        entered += std::holds_alternative<EdgeEntered>(e);
        left += std::holds_alternative<EdgeLeft>(e);
    }
    CHECK(lines == 30);
    CHECK(entered > 0);
    CHECK(left <= entered);
}

TEST_CASE("the scan-line step bound ends it with its own event", "[scanline][bound]") {
    const Scene s = random_triangles({.count = 30, .seed = 5, .size = 2});
    const Viewport vp{40, 30};
    ScanLineOptions o = scan_line_options(s, vp, DepthFormat::int24);
    o.max_crossings = 10;
    auto m = scan_line(project_polygons(s, vp), o);
    ScanLineEvent last = ScanFinished{};
    for (const auto& e : m) last = e;
    CHECK(std::holds_alternative<ScanStepBoundReached>(last));
    CHECK(std::move(m).result().bounded);
}
