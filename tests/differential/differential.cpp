// SPDX-License-Identifier: MIT
// The differential test: generated scenes built to break hidden-surface algorithms (scene_families.h), every
// hidden-surface algorithm and setting drawn into an id image, compared pixel by pixel with OpenGL (Mesa's
// llvmpipe through EGL: another rasteriser, written by others) and with the double-precision ray cast without
// acceleration (the plainest reference). Each differing pixel is classed as edge, depth tie or unexplained
// (pixel_classes.h); unexplained must be 0. A timing guard fails a scene that takes over 100 times the median of
// its family for the same algorithm. Exit 1 on any unexplained pixel, timing failure, bound reached or refusal.
//   differential [--scenes N] [--size WxH] [--family NAME]
//   differential --write FAMILY SEED FILE     one generated scene as a scene file (to look at it, or to keep it)
// CI runs a quick size (ctest); scripts/differential a larger one.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "gui/gl_peer.h"
#include "pixel_classes.h"
#include "renderers.h"
#include "scene/save_scene.h"
#include "scene_families.h"
#include "zbuffer/zbuffer_fill.h"

namespace {

using namespace hsr;
using algo::DepthFormat;
using algo::SceneId;

// OpenGL: each polygon as a fan of triangles in clip space, coloured by its index; the index mapped back to its id.
test::Drawn opengl(const algo::Scene& s, algo::Viewport vp) {
    const glm::dmat4 m = algo::view_projection(s.camera);
    std::vector<test::Triangle> tris;
    std::vector<SceneId> id_of;
    for (const algo::ScenePolygon& p : s.polygons)
        for (std::size_t k = 1; k + 1 < p.vertices.size(); ++k) {
            tris.push_back({{m * p.vertices[0], m * p.vertices[k], m * p.vertices[k + 1]}});
            id_of.push_back(p.id);
        }
    test::Drawn d;
    for (const int index : test::gl_ids(tris, vp.width, vp.height)) d.ids.push_back(index == 0 ? 0 : id_of.at(std::size_t(index - 1)));
    return d;
}

std::vector<test::Renderer> renderers() {
    std::vector<test::Renderer> r = test::cpu_renderers();
    r.push_back({"opengl (llvmpipe)", {DepthFormat::int24}, opengl});
    return r;
}

struct Totals {
    test::Tally vs_ray, vs_gl;
    std::uint64_t bounded = 0, refused = 0, slow = 0;
    std::vector<double> ms;
};

struct Timing {
    std::string family, renderer;
    std::uint32_t seed;
    double ms;
};

double ms_of(const std::function<void()>& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Compares and prints the first few unexplained pixels (to find them).
void compare(const std::vector<SceneId>& ours, const std::vector<SceneId>& reference, const char* reference_name,
             const test::Outlines& scene, const test::Outlines& parts, const test::TieRule& tie, algo::Viewport vp, test::Tally& t,
             const std::string& where) {
    static std::size_t printed = 0;
    std::vector<std::string> first;
    t += test::compare_images(ours, reference, vp, scene, parts, tie, &first, 12);
    for (const std::string& pixel : first)
        if (printed++ < 12) std::fprintf(stderr, "unexplained: %s against %s, pixel %s\n", where.c_str(), reference_name, pixel.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    int scenes = 3, width = 96, height = 72;
    std::string only;
    if (argc == 5 && std::strcmp(argv[1], "--write") == 0) {
        for (const test::SceneFamily& family : test::scene_families())
            if (family.name == argv[2]) {
                std::FILE* out = std::fopen(argv[4], "w");
                if (!out) return std::fprintf(stderr, "differential: cannot write %s\n", argv[4]), 1;
                const std::string toml = algo::scene_toml(family.make(std::uint32_t(std::atoi(argv[3])), 4.0 / 3));
                std::fputs(toml.c_str(), out);
                return std::fclose(out) == 0 ? 0 : 1;
            }
        return std::fprintf(stderr, "differential: no family %s\n", argv[2]), 2;
    }
    for (int k = 1; k < argc; ++k) {
        const std::string a = argv[k];
        if (a == "--scenes" && k + 1 < argc) scenes = std::atoi(argv[++k]);
        else if (a == "--size" && k + 1 < argc && std::sscanf(argv[++k], "%dx%d", &width, &height) == 2) {}
        else if (a == "--family" && k + 1 < argc) only = argv[++k];
        else return std::fprintf(stderr, "usage: differential [--scenes N] [--size WxH] [--family NAME]\n"), 2;
    }
    if (scenes < 1 || width < 1 || height < 1 || width > 4096 || height > 4096)
        return std::fprintf(stderr, "differential: --scenes ≥ 1 and --size from 1x1 to 4096x4096\n"), 2;
    const test::GlContext gl(width, height);
    if (!gl.context) return std::fprintf(stderr, "differential: no OpenGL context: %s\n", SDL_GetError()), 1;
    const algo::Viewport vp{width, height};
    const std::vector<test::Renderer> list = renderers();
    std::map<std::string, Totals> totals;
    std::vector<Timing> timings;
    int scene_count = 0;
    for (const test::SceneFamily& family : test::scene_families()) {
        if (!only.empty() && family.name != only) continue;
        for (std::uint32_t seed = 1; seed <= std::uint32_t(scenes); ++seed, ++scene_count) {
            const algo::Scene scene = family.make(seed, double(width) / height);
            const std::string where = family.name + " seed " + std::to_string(seed);
            const test::Drawn reference = test::ray_cast(scene, vp);
            const test::Drawn gl_drawn = opengl(scene, vp);
            const test::Outlines outlines = test::scene_outlines(scene, vp);
            const algo::ZBufferOptions zo = algo::zbuffer_options(scene, vp, DepthFormat::int24);
            for (const test::Renderer& r : list) {
                Totals& t = totals[r.name];
                test::Drawn d;
                try {
                    const double ms = ms_of([&] { d = r.draw(scene, vp); });
                    t.ms.push_back(ms);
                    timings.push_back({family.name, r.name, seed, ms});
                } catch (const std::exception& e) {
                    ++t.refused;
                    std::fprintf(stderr, "refused: %s by %s: %s\n", where.c_str(), r.name.c_str(), e.what());
                    continue;
                }
                if (d.bounded) {
                    ++t.bounded;
                    std::fprintf(stderr, "bound reached: %s by %s\n", where.c_str(), r.name.c_str());
                }
                test::TieRule ray_tie{r.formats.empty() ? std::vector{DepthFormat::int24} : r.formats, zo.range, zo.perspective};
                test::TieRule gl_tie = ray_tie;
                gl_tie.formats.push_back(DepthFormat::int24);  // OpenGL's depth buffer here
                compare(d.ids, reference.ids, "ray cast", outlines, d.parts, ray_tie, vp, t.vs_ray, where + " " + r.name);
                compare(d.ids, gl_drawn.ids, "OpenGL", outlines, d.parts, gl_tie, vp, t.vs_gl, where + " " + r.name);
            }
        }
    }
    // The timing guard: a scene over 100× its family's median for the same renderer (and over 20 ms, below which a
    // shared machine's scheduling alone can make a hundredfold)
    std::map<std::pair<std::string, std::string>, std::vector<double>> by_family;
    for (const Timing& t : timings) by_family[{t.family, t.renderer}].push_back(t.ms);
    for (auto& [key, ms] : by_family) std::sort(ms.begin(), ms.end());
    for (const Timing& t : timings) {
        const auto& ms = by_family[{t.family, t.renderer}];
        const double median = ms[ms.size() / 2];
        if (t.ms > 100 * median && t.ms > 20) {
            ++totals[t.renderer].slow;
            std::fprintf(stderr, "too slow: %s seed %u by %s: %.1f ms, the family's median %.3f ms\n", t.family.c_str(), t.seed,
                         t.renderer.c_str(), t.ms, median);
        }
    }
    std::printf("differential: %d scenes in %zu families at %dx%d, references: ray cast (no acceleration) and OpenGL (%s)\n",
                scene_count, only.empty() ? test::scene_families().size() : 1, width, height, gl.renderer());
    std::printf("%-30s %11s | %-34s | %-34s | %9s %6s\n", "", "pixels", "against the ray cast", "against OpenGL", "median", "");
    std::printf("%-30s %11s | %8s %8s %8s %7s | %8s %8s %8s %7s | %9s %6s\n", "algorithm", "compared", "differ", "edge", "tie",
                "unexpl", "differ", "edge", "tie", "unexpl", "ms", "slow");
    bool failed = false;
    for (const test::Renderer& r : list) {
        Totals& t = totals[r.name];
        std::sort(t.ms.begin(), t.ms.end());
        const double median = t.ms.empty() ? 0 : t.ms[t.ms.size() / 2];
        std::printf("%-30s %11llu | %8llu %8llu %8llu %7llu | %8llu %8llu %8llu %7llu | %9.3f %6llu%s\n", r.name.c_str(),
                    (unsigned long long)t.vs_ray.compared, (unsigned long long)t.vs_ray.differ, (unsigned long long)t.vs_ray.edge,
                    (unsigned long long)t.vs_ray.tie, (unsigned long long)t.vs_ray.unexplained, (unsigned long long)t.vs_gl.differ,
                    (unsigned long long)t.vs_gl.edge, (unsigned long long)t.vs_gl.tie, (unsigned long long)t.vs_gl.unexplained, median,
                    (unsigned long long)t.slow, t.bounded || t.refused ? "  (bound or refusal)" : "");
        failed |= t.vs_ray.unexplained || t.vs_gl.unexplained || t.slow || t.bounded || t.refused;
    }
    std::printf("differential: %s\n", failed ? "FAILED (unexplained pixels, a slow scene, a bound or a refusal above)" : "every difference explained");
    return failed ? 1 : 0;
}
