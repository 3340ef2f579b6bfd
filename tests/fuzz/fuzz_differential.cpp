// SPDX-License-Identifier: MIT
// libFuzzer: the differential test with the scenes made by the fuzzer. The bytes become up to 6 triangles inside
// the view (coordinates on a fine grid in ±4, so that near-coplanar stacks, slivers, shared edges and piercing
// pairs all come up), sometimes an orthographic camera; every hidden-surface renderer draws them at 48×36 and each
// pixel that differs from the double-precision ray cast must be an edge or a depth tie (tests/differential).
// An unexplained pixel aborts with the renderer's name and the pixel.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/numeric.h"
#include "renderers.h"
#include "zbuffer/zbuffer_fill.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace hsr;
    std::size_t at = 0;
    const auto byte = [&]() -> int { return at < size ? data[at++] : 0; };
    const auto coordinate = [&]() { return (byte() * 256 + byte()) / 65535.0 * 8.0 - 4.0; };  // ±4 on a 1/8192 grid
    algo::Scene s;
    s.camera = {.eye = {0.3, 0.4, 9}, .target = {0, 0, 0}, .fov_y = 50, .aspect = 48.0 / 36, .near = 1, .far = 30};
    if (byte() % 5 == 0) {
        s.camera.projection = algo::Projection::orthographic;
        s.camera.box[0] = -6, s.camera.box[1] = 6, s.camera.box[2] = -4.5, s.camera.box[3] = 4.5;
    }
    const int triangles = 1 + byte() % 6;
    for (int p = 0; p < triangles && at < size; ++p) {
        algo::ScenePolygon t{algo::SceneId(p + 1), {std::uint8_t(40 * p), 120, 200}, {}};
        for (int k = 0; k < 3; ++k) t.vertices.emplace_back(coordinate(), coordinate(), coordinate(), 1.0);
        s.polygons.push_back(std::move(t));
    }
    const algo::Viewport vp{48, 36};
    try {
        const test::Drawn reference = test::ray_cast(s, vp);
        const test::Outlines outlines = test::scene_outlines(s, vp);
        const algo::ZBufferOptions zo = algo::zbuffer_options(s, vp, algo::DepthFormat::int24);
        for (const test::Renderer& r : test::cpu_renderers()) {
            const test::Drawn d = r.draw(s, vp);
            if (d.bounded) continue;  // an unfinished picture is refused by render, not compared
            const test::TieRule tie{r.formats.empty() ? std::vector{algo::DepthFormat::int24} : r.formats, zo.range, zo.perspective};
            std::vector<std::string> first;
            const test::Tally t = test::compare_images(d.ids, reference.ids, vp, outlines, d.parts, tie, &first, 3);
            if (t.unexplained == 0) continue;
            std::fprintf(stderr, "fuzz_differential: %s differs from the ray cast at %llu unexplained pixels, first %s\n",
                         r.name.c_str(), (unsigned long long)t.unexplained, first.empty() ? "?" : first.front().c_str());
            std::abort();
        }
    } catch (const algo::InvalidInput&) {  // a degenerate triangle (no area) is refused: a well-defined result
    }
    return 0;
}
