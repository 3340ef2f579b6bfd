// SPDX-License-Identifier: MIT
// What every fuzz target does with a scene that loaded: run each machine on it, small and bounded, where an input
// that is wrong may only be refused with InvalidInput (a clear error); anything else, a crash, a sanitizer report or
// a hang, is a bug the fuzzer reports.
#pragma once

#include "bsp/bsp_scene.h"
#include "clipping/clip_scene.h"
#include "compositing/compositing.h"
#include "core/numeric.h"
#include "culling/pipeline.h"
#include "depth_sort/depth_sort.h"
#include "horizon/floating_horizon.h"
#include "portals/portal_render.h"
#include "raycast/ray_cast.h"
#include "abuffer/a_buffer.h"
#include "forms/general_forms.h"
#include "volumes/intersection_test.h"
#include "perspective/perspective_transform.h"
#include "roberts/hidden_lines.h"
#include "zbuffer/classic_scanline.h"
#include "zbuffer/zbuffer_fill.h"

namespace hsr::fuzz {

template <class F>
void refused_or_done(F&& f) {
    try {
        f();
    } catch (const algo::InvalidInput&) {  // a clear refusal is a well-defined result
    }
}

inline void run_machines(const algo::Scene& s) {
    if (s.polygons.size() > 48 || s.segments.size() > 48 || s.floor_plan.cells.size() > 24) return;  // keep each run fast
    using namespace hsr::algo;
    for (const ClipAlgorithm a : {ClipAlgorithm::cohen_sutherland, ClipAlgorithm::liang_barsky, ClipAlgorithm::sutherland_hodgman})
        refused_or_done([&] { (void)clip_scene(clip_job(s), a).run_to_end(); });
    if (s.terrain.rows > 0 && std::size_t(s.terrain.rows) * std::size_t(s.terrain.columns) <= 4096)
        refused_or_done([&] { (void)floating_horizon(s.terrain, {.columns = 24}).run_to_end(); });
    if (s.coordinates != Coordinates::world) return;
    refused_or_done([&] {
        (void)zbuffer_fill(project_polygons(s, {16, 12}), zbuffer_options(s, {16, 12}, DepthFormat::int16, EventDetail::polygon)).run_to_end();
    });
    refused_or_done([&] { (void)depth_sort(sort_polygons(s), {.max_splits = 64, .max_pairs = 20000}).run_to_end(); });
    refused_or_done([&] { (void)composite(layers_along(s, centre_ray(s.camera))).run_to_end(); });
    refused_or_done([&] { (void)roberts(s, {.max_tests = 20000}).run_to_end(); });
    refused_or_done([&] { (void)perspective_transform(s, {.max_comparisons = 20000}).run_to_end(); });
    refused_or_done([&] {
        (void)intersection_test(s, rays_of(s), {.bounding = {.volume = VolumeKind::hulls}, .max_steps = 20000}).run_to_end();
    });
    refused_or_done([&] { (void)general_forms(s, {.pixels = 24, .max_steps = 20000}).run_to_end(); });
    refused_or_done([&] { (void)a_buffer(s, {24, 18}, {.mask_size = 4, .max_fragments = 20000}).run_to_end(); });
    refused_or_done([&] {
        ScanLineOptions o = scan_line_options(s, {16, 12}, DepthFormat::int24);
        o.max_crossings = 20000;
        (void)classic_scan_line(project_polygons(s, {16, 12}), {.line = o}).run_to_end();
    });
    refused_or_done([&] {
        BspJob job = bsp_job(s, SplitterRule::balanced);
        job.options.max_depth = 64, job.options.max_polygons = 4096;
        (void)bsp_scene(std::move(job)).run_to_end();
    });
    refused_or_done([&] { (void)ray_cast(s, {.viewport = {8, 6}, .acceleration = Acceleration::grid, .detail = RayDetail::ray}).run_to_end(); });
    refused_or_done([&] { (void)ray_cast(s, {.viewport = {8, 6}, .acceleration = Acceleration::bvh, .detail = RayDetail::ray}).run_to_end(); });
    refused_or_done([&] {
        (void)run_pipeline(s, {.stages = {Stage::back_face, Stage::frustum, Stage::detail, Stage::occluders, Stage::portals, Stage::hiz},
                               .viewport = {16, 12}});
    });
    refused_or_done([&] {  // solid occluders and fusion
        (void)run_pipeline(s, {.stages = {Stage::occluders}, .viewport = {16, 12}, .occluders = OccluderKind::solid, .fusion = true});
    });
    if (!s.floor_plan.cells.empty())
        refused_or_done([&] {
            const CellModel m = cell_model(s);
            const CellBsp bsp = build_cell_bsp(m);
            const Pvs pvs = build_pvs(&m, {.max_depth = 32, .max_tests = 20000}).run_to_end();
            (void)portal_render(&m, &bsp, &pvs, m.camera, {.max_depth = 16, .max_visits = 2000}).run_to_end();
        });
}

}  // namespace hsr::fuzz
