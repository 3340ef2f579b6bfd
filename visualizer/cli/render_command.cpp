// SPDX-License-Identifier: MIT
#include "cli/render_command.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <new>
#include <stdexcept>

#include <unistd.h>

#include <glm/geometric.hpp>

#include "core/plane.h"
#include "scene/input_file.h"
#include "analysis/painters.h"
#include "cli/ids_png.h"
#include "state/arguments.h"
#include "state/interrupt.h"
#include "state/memory_budget.h"
#include "raster/image.h"
#include "core/work_meter.h"
#include "culling/pipeline.h"
#include "depth_sort/depth_sort.h"
#include "raster/screen_polygon.h"
#include "raycast/ray_cast.h"
#include "scene/generated_scenes.h"
#include "scene/load_scene.h"
#include "zbuffer/classic_scanline.h"
#include "zbuffer/scanline.h"
#include "zbuffer/zbuffer_fill.h"
#include "scene/renderer_names.h"

namespace hsr::viz {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

algo::SplitterRule splitter_named(const std::string& s) {
    if (const auto rule = algo::parse_splitter_rule(s)) return *rule;
    throw std::runtime_error("unknown splitter \"" + s + "\"; expected " + std::string(algo::splitter_rule_names));
}

algo::DepthFormat format_named(const std::string& s) {
    using F = algo::DepthFormat;
    for (F f : {F::int16, F::int24, F::int32, F::float32, F::float32_reversed, F::linear24})
        if (s == format_id(f)) return f;
    throw std::runtime_error("unknown depth format \"" + s + "\"; expected int16, int24, int32, float32, float32-reversed or linear24");
}

algo::Acceleration acceleration_named(const std::string& s) {
    if (s == "none") return algo::Acceleration::none;
    if (s == "grid") return algo::Acceleration::grid;
    if (s == "octree") return algo::Acceleration::octree;
    if (s == "bvh") return algo::Acceleration::bvh;
    throw std::runtime_error("unknown acceleration \"" + s + "\"; expected none, grid, octree or bvh");
}

algo::Image render_bsp(const algo::Scene& scene, const RenderOptions& o, algo::Viewport vp, algo::WorkMeter& meter) {
    analysis::BspPainting p = analysis::paint_bsp(scene, splitter_named(o.splitter), vp, &meter);
    std::printf("bsp (%s): %zu polygons in, %zu in the tree after %u splits and %llu classifications, %zu nodes, "
                "depth %u, built in %.3f ms\n",
                o.splitter.c_str(), scene.polygons.size(), p.tree.held(), p.tree.splits,
                static_cast<unsigned long long>(p.tree.classifications), p.tree.nodes.size(), p.tree.depth, p.build_ms);
    if (p.tree.bounded)
        throw std::runtime_error("the BSP build stopped at a step bound (depth, polygons or classifications); no image written");
    return std::move(p.image);
}

// The culling pipeline, then the z-buffer on what is left: one line per stage.
algo::Image render_culled(const algo::Scene& scene, const RenderOptions& o, algo::Viewport vp, algo::WorkMeter&) {
    const auto start = Clock::now();
    algo::OccluderKind occluders = algo::OccluderKind::planar;
    for (const algo::OccluderKind k : {algo::OccluderKind::planar, algo::OccluderKind::proxy, algo::OccluderKind::solid})
        if (o.occluders == to_string(k)) occluders = k;
    algo::PipelineResult r = algo::run_pipeline(
        scene, {.stages = algo::parse_stages(*o.cull), .viewport = vp, .format = format_named(o.format), .occluders = occluders, .fusion = o.fusion});
    const double total = ms_since(start);
    std::printf("built once (the octree; the solid occluders, cell BSP and PVS when asked for) in %.3f ms\n", r.hierarchy_milliseconds);
    for (const algo::StageReport& s : r.stages) {
        const std::string name(to_string(s.stage));
        if (!s.ran && s.stage == algo::Stage::hse && r.frame.image.width > 0)
            std::printf("%-10s done by hiz, which renders as it culls\n", name.c_str());
        else if (!s.ran) std::printf("%-10s left out of the pipeline\n", name.c_str());
        else std::printf("%-10s in %u, left out %u, passed on %u, %.3f ms\n", name.c_str(), s.in, s.left_out, s.passed, s.milliseconds);
    }
    std::printf("frame: %zu polygons, %llu depth tests, %.3f ms in all\n", r.kept.size(), (unsigned long long)r.frame.tested, total);
    return std::move(r.frame.image);
}

algo::Image render_zbuffer(const algo::Scene& scene, const RenderOptions& o, algo::Viewport vp, algo::WorkMeter& meter) {
    if (o.cull) return render_culled(scene, o, vp, meter);
    const algo::DepthFormat format = format_named(o.format);
    const auto start = Clock::now();
    meter.stage("z-buffer", "polygons", double(scene.polygons.size()));
    algo::FrameDepth f = algo::drain(
        algo::zbuffer_fill(algo::project_polygons(scene, vp), algo::zbuffer_options(scene, vp, format, algo::EventDetail::polygon)),
        &meter, [](const algo::ZBufferEvent& e, double& filled) {
            filled += std::holds_alternative<algo::PolygonFillFinished>(e) || std::holds_alternative<algo::PolygonSkipped>(e);
        });
    std::printf("zbuffer (%s): %zu polygons, %llu depth tests, %llu writes in %.3f ms\n", std::string(to_string(format)).c_str(),
                scene.polygons.size(), (unsigned long long)f.tested, (unsigned long long)f.written, ms_since(start));
    if (f.tested > 0 && f.written == 0)  // a blank picture that is right for the format, said so it is not taken for a bug
        std::fprintf(stderr, "hsrviz: no pixel passed the depth test: in %s every depth rounds to the far plane's code "
                             "(near %g, far %g); try --format float32-reversed or a larger near\n",
                     std::string(to_string(format)).c_str(), scene.camera.near, scene.camera.far);
    return std::move(f.image);
}

// The hybrid scan line (a one-line z-buffer) or the classic one (the polygon table's planes where spans begin).
algo::Image render_scan_line(const algo::Scene& scene, const RenderOptions& o, algo::Viewport vp, algo::WorkMeter& meter, bool classic) {
    const algo::DepthFormat format = format_named(o.format);
    const auto start = Clock::now();
    algo::ScanLineOptions options = algo::scan_line_options(scene, vp, format);
    options.tell_crossings = false;
    meter.stage("scan line", "rows", double(vp.height));
    std::uint64_t spans = 0;
    auto polygons = algo::project_polygons(scene, vp);
    algo::FrameDepth f = algo::drain(classic ? algo::classic_scan_line(std::move(polygons), {.line = options})
                                             : algo::scan_line(std::move(polygons), options),
                                     &meter,
                                     [&](const algo::ScanLineEvent& e, double& rows) {
                                         spans += std::holds_alternative<algo::SpanColored>(e);
                                         if (const auto* line = std::get_if<algo::ScanLineStarted>(&e)) rows = line->y;
                                     });
    std::printf("%s (%s): %zu polygons, %llu spans in %.3f ms\n", classic ? "scanline-classic" : "scanline", std::string(to_string(format)).c_str(),
                scene.polygons.size(), (unsigned long long)spans, ms_since(start));
    return std::move(f.image);
}

algo::Image render_scanline(const algo::Scene& scene, const RenderOptions& o, algo::Viewport vp, algo::WorkMeter& meter) {
    return render_scan_line(scene, o, vp, meter, false);
}

algo::Image render_scanline_classic(const algo::Scene& scene, const RenderOptions& o, algo::Viewport vp, algo::WorkMeter& meter) {
    return render_scan_line(scene, o, vp, meter, true);
}

algo::Image render_raycast(const algo::Scene& scene, const RenderOptions& o, algo::Viewport vp, algo::WorkMeter& meter) {
    const algo::Acceleration a = acceleration_named(o.acceleration);
    const auto start = Clock::now();
    meter.stage("ray cast", "rays", double(vp.width) * double(vp.height));
    algo::RayCastResult r = algo::drain(algo::ray_cast(scene, {.viewport = vp, .acceleration = a, .detail = algo::RayDetail::ray}),
                                        &meter, [](const algo::RayCastEvent& e, double& rays) { rays += std::holds_alternative<algo::RayFinished>(e); });
    std::printf("raycast (%s): %zu polygons, %llu primitive tests in %.3f ms\n", std::string(to_string(a)).c_str(),
                scene.polygons.size(), (unsigned long long)r.tests, ms_since(start));
    return std::move(r.image);
}

algo::Image render_depth_sort(const algo::Scene& scene, const RenderOptions&, algo::Viewport vp, algo::WorkMeter& meter) {
    analysis::DepthSortPainting p = analysis::paint_depth_sort(scene, vp, &meter);
    const algo::DepthSortResult& r = p.sorted;
    std::printf("depth-sort: %zu polygons, %llu pairs examined, %u moves, %u splits, sorted in %.3f ms\n", scene.polygons.size(),
                (unsigned long long)r.pairs, r.moves, r.splits, p.sort_ms);
    if (r.bounded)  // the painting would be of an unfinished sort: a wrong picture, so none
        throw std::runtime_error("depth sort stopped at its step bound (" + std::to_string(r.pairs) + " pairs, " +
                                 std::to_string(r.splits) + " splits); no image written");
    return std::move(p.image);
}

// On a terminal one line rewritten in place; into a log file a line every ten seconds.
void progress_on_stderr(const algo::WorkProgress& p) {
    static const bool terminal = isatty(STDERR_FILENO) != 0;
    static double last_logged = -10;
    if (terminal && p.finished) {
        std::fprintf(stderr, "\r\x1b[K");  // the line is cleared for what the command prints next
    } else if (terminal) {
        std::fprintf(stderr, "\r%s (Ctrl+C stops)\x1b[K", p.sentence().c_str());
    } else if (!p.finished && (p.seconds < last_logged || p.seconds - last_logged >= 10)) {
        std::fprintf(stderr, "hsrviz: %s\n", p.sentence().c_str());
        last_logged = p.seconds;
    }
    std::fflush(stderr);
}

// Each polygon's colour shaded by its turn to a light at the eye (flat, one shade per polygon), so that a mesh of one
// colour (a teapot, a bunny) shows its form instead of its silhouette: full colour facing the eye, 35 % edge-on.
void shade_by_facing_the_eye(algo::Scene& scene) {
    for (algo::ScenePolygon& p : scene.polygons) {
        const std::vector<algo::Vec3> corners(p.vertices.begin(), p.vertices.end());  // world: w = 1
        algo::Plane plane;
        if (corners.size() < 3 || !algo::plane_of(corners, plane)) continue;
        const algo::Vec3 to_eye = scene.camera.projection == algo::Projection::orthographic ? scene.camera.eye - scene.camera.target
                                                                                           : scene.camera.eye - algo::centroid(corners);
        const double facing = std::abs(glm::dot(plane.n, to_eye)) / glm::length(to_eye);
        if (!std::isfinite(facing)) continue;  // no area, or the eye on it: as given
        const double shade = 0.35 + 0.65 * facing;
        p.color = {std::uint8_t(std::lround(p.color.r * shade)), std::uint8_t(std::lround(p.color.g * shade)), std::uint8_t(std::lround(p.color.b * shade))};
    }
}

// What a render needs: bytes per triangle of each algorithm, measured (peak resident memory by /usr/bin/time, less
// the 15 MB of a render of city:12) on city:300000 and city:1000000 at 512×512, the larger figure with a fifth more.
// One figure for all (1200, the ray cast's grid in the window) refused city:20000000 as 'about 22.4 GB' where the
// z-buffer peaks near 3.2 GB at 10^7 (issue 53, item 13).
//   zbuffer 409 / 332, scanline 428, scanline-classic 410, raycast (grid) 720 / 680, depth-sort 258 (city:100000)
//   bsp 4750 on city:100000; 886 MB when its build stops at its step bound on city:300000 (the tree it may grow
//   is bounded, not the scene): per triangle up to that, and the scene's own bytes beyond it.
std::uint64_t render_memory_estimate(const RenderOptions& o, std::uint64_t triangles, std::uint64_t pixels) {
    constexpr std::uint64_t program = 64ull << 20;
    if (o.algorithm == "bsp") {
        constexpr std::uint64_t per_triangle = 5900, scene_bytes = 520, tree_at_bound = 1100ull << 20;
        return program + std::min(triangles * per_triangle, tree_at_bound + triangles * scene_bytes) + pixels * bytes_per_pixel;
    }
    const std::uint64_t per_triangle = o.algorithm == "raycast" ? 870 : o.algorithm == "depth-sort" ? 320
                                       : o.cull                   ? bytes_per_triangle  // the octree and occluders: the window's figure
                                                                  : 520;
    return program + triangles * per_triangle + pixels * bytes_per_pixel;
}

algo::Scene generated_or_loaded(const std::string& name) {
    if (auto generated = algo::generated_scene(name)) return std::move(*generated);
    return algo::load_scene(name);
}

}  // namespace

int run_render(const RenderOptions& o) {
    try {
        const auto size = parse_size(o.size);
        if (!size) throw std::runtime_error("--size: expected WxH from 1x1 to 16384x16384, got " + algo::printable(o.size, 60));
        const auto [w, h] = *size;
        const std::string work = "render of " + algo::printable(o.scene, 60) + " at " + o.size;
        // Before anything is generated or allocated: a generated scene's size is in its name
        require_memory(render_memory_estimate(o, algo::generated_triangles(o.scene).value_or(0), std::uint64_t(w) * std::uint64_t(h)), work);
        algo::Scene scene = generated_or_loaded(o.scene);
        for (const std::string& note : scene.notes) std::fprintf(stderr, "hsrviz: %s\n", algo::printable(note, 2000).c_str());
        require_memory(render_memory_estimate(o, scene.polygons.size(), std::uint64_t(w) * std::uint64_t(h)), work);
        if (const auto refused = algo::polygons_not_convex(scene); !refused.empty())
            throw std::runtime_error(refused.front() + (refused.size() > 1 ? " (and " + std::to_string(refused.size() - 1) + " more)" : ""));
        if (o.cull && o.algorithm != "zbuffer") throw std::runtime_error("--cull works with --algorithm zbuffer");
        if (o.occluders != "planar" && o.occluders != "proxy" && o.occluders != "solid")
            throw std::runtime_error("--occluders: expected planar, proxy or solid, got \"" + algo::printable(o.occluders, 60) + "\"");
        if (scene.terrain.rows > 0 && scene.polygons.empty())  // an empty picture with exit 0 was what it gave
            throw std::runtime_error(algo::printable_name(o.scene) + ": render draws polygons, and this scene is a [terrain] (the floating "
                                     "horizon's): play it in the window or with `hsrviz trace`");
        if (scene.terrain.rows > 0) std::fprintf(stderr, "hsrviz: %s: the [terrain] is not drawn (render draws polygons)\n", algo::printable_name(o.scene).c_str());
        if (scene.coordinates != algo::Coordinates::world)
            throw std::runtime_error(algo::printable_name(o.scene) + ": render needs world coordinates");
        if (o.eye) {
            const auto e = parse_point(*o.eye);
            if (!e) throw std::runtime_error("--eye: expected X,Y,Z (finite numbers within ±1e100), got " + algo::printable(*o.eye, 60));
            if (glm::length(scene.camera.target - *e) == 0) throw std::runtime_error("--eye: the eye is at the camera's target; it must look at it from somewhere");
            if (glm::length(glm::cross(scene.camera.target - *e, scene.camera.up)) == 0)
                throw std::runtime_error("--eye: from there the camera looks along its up direction; move the eye sideways");
            scene.camera.eye = *e;
        }
        scene.camera.aspect = double(w) / double(h);
        shade_by_facing_the_eye(scene);
        if (o.ids)
            for (const auto& p : scene.polygons)
                if (p.id < 1 || p.id > 65535)
                    throw std::runtime_error(algo::printable_name(o.scene) + ": polygon id " + std::to_string(p.id) +
                                             " does not fit the 16-bit id image (ids 1 to 65535)");

        const std::map<std::string, std::function<algo::Image(const algo::Scene&, const RenderOptions&, algo::Viewport, algo::WorkMeter&)>>
            renderers{{"bsp", render_bsp}, {"zbuffer", render_zbuffer}, {"scanline", render_scanline}, {"scanline-classic", render_scanline_classic},
                      {"raycast", render_raycast}, {"depth-sort", render_depth_sort}};
        const auto renderer = renderers.find(o.algorithm);
        if (renderer == renderers.end())
            throw std::runtime_error("unknown algorithm \"" + algo::printable(o.algorithm, 60) + "\" for render; expected " + algo::renderer_list());
        StopOnInterrupt ctrl_c;
        algo::WorkMeter meter(progress_on_stderr, &ctrl_c.asked);
        const algo::Image image = renderer->second(scene, o, {w, h}, meter);
        meter.look();  // a Ctrl+C during the last events, or during work that is not metered (the culling pipeline)
        if (!write_colour_png(o.out, image, &ctrl_c.asked)) throw std::runtime_error("cannot write " + algo::printable_name(o.out));
        try {
            if (o.ids && !write_ids_png(*o.ids, image, &ctrl_c.asked)) throw std::runtime_error("cannot write " + algo::printable_name(*o.ids));
        } catch (...) {  // no colour picture without the ids asked for beside it
            std::error_code ec;
            if (std::filesystem::is_regular_file(o.out, ec)) std::filesystem::remove(o.out, ec);
            throw;
        }
        std::printf("wrote %s%s%s\n", algo::printable_name(o.out).c_str(), o.ids ? " and " : "", o.ids ? algo::printable_name(*o.ids).c_str() : "");
        return 0;
    } catch (const algo::WorkStopped&) {
        std::fprintf(stderr, "%shsrviz: stopped (Ctrl+C); no image written\n", isatty(STDERR_FILENO) ? "\n" : "");
        return 130;  // the shell's code for a command ended by SIGINT
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "hsrviz: out of memory: the render needs more than this machine (or its limits) allow; no image written\n");
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "hsrviz: %s\n", algo::printable(e.what(), 2000).c_str());
        return 1;
    }
}

}  // namespace hsr::viz
