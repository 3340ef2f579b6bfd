// SPDX-License-Identifier: MIT
#include "culling/pipeline.h"

#include <algorithm>
#include <optional>

#include "culling/backface.h"
#include "culling/hiz.h"
#include "culling/occluders.h"
#include "core/numeric.h"
#include "portals/portal_render.h"

namespace hsr::algo {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }


}  // namespace

std::string_view to_string(Stage s) {
    switch (s) {
        case Stage::back_face: return "back-face";
        case Stage::frustum: return "frustum";
        case Stage::detail: return "detail";
        case Stage::occluders: return "occluders";
        case Stage::portals: return "portals";
        case Stage::hiz: return "hiz";
        case Stage::hse: return "hse";
    }
    return "?";
}

std::vector<Stage> parse_stages(std::string_view list) {
    std::vector<Stage> out;
    while (!list.empty()) {
        const std::size_t comma = list.find(',');
        const std::string_view name = list.substr(0, comma);
        const auto* s = std::find_if(std::begin(all_stages), std::end(all_stages), [&](Stage x) { return to_string(x) == name; });
        if (s == std::end(all_stages))
            throw InvalidInput("unknown culling stage \"" + std::string(name) + "\" (expected back-face, frustum, detail, occluders, portals, hiz)");
        out.push_back(*s);
        list = comma == std::string_view::npos ? std::string_view{} : list.substr(comma + 1);
    }
    return out;
}

PipelineResult run_pipeline(const Scene& given, const PipelineOptions& o) {
    // A floor plan plays as its rooms' walls, floors and objects
    std::optional<CellModel> model;
    if (!given.floor_plan.cells.empty()) model = cell_model(given);
    const Scene rooms = model ? model_scene(*model) : Scene{};
    const Scene& scene = model ? rooms : given;
    const std::size_t n = scene.polygons.size();
    const auto wanted = [&](Stage s) { return s == Stage::hse || std::find(o.stages.begin(), o.stages.end(), s) != o.stages.end(); };
    PipelineResult out;
    out.kept.assign(n, 1);
    const ZBufferOptions zo = zbuffer_options(scene, o.viewport, o.format, EventDetail::polygon);
    // The hierarchy the stages walk: pre-processing, built once
    const auto t_hierarchy = Clock::now();
    const Hierarchy hierarchy = build_hierarchy(polygon_boxes(scene), {.kind = o.hierarchy}).run_to_end();
    // and the objects that are solid occluders, found once like the hierarchy
    const bool solids_wanted = o.occluders == OccluderKind::solid && wanted(Stage::occluders);
    const std::vector<std::vector<std::uint32_t>> solids = solids_wanted ? convex_solids(scene) : std::vector<std::vector<std::uint32_t>>{};
    out.hierarchy_milliseconds = ms_since(t_hierarchy);
    bool rendered = false;
    for (const Stage stage : all_stages) {
        StageReport r{stage};
        r.in = std::uint32_t(std::count(out.kept.begin(), out.kept.end(), 1));
        r.candidates = out.kept;
        if (!wanted(stage) || (stage == Stage::hse && rendered) || (stage == Stage::portals && !model)) {
            r.passed = r.in;
            out.stages.push_back(r);
            continue;
        }
        r.ran = true;
        const auto t = Clock::now();
        std::vector<std::uint8_t> keep(n, 1);
        switch (stage) {
            case Stage::back_face: {
                std::vector<Face> faces;
                for (const auto& p : scene.polygons) {
                    Face f{p.id, {}};
                    for (const auto& v : p.vertices) f.vertices.emplace_back(v);
                    faces.push_back(std::move(f));
                }
                const auto front = cull_back_faces(std::move(faces), scene.camera, BackfaceTest::plane_equation).run_to_end();
                std::fill(keep.begin(), keep.end(), 0);
                std::size_t k = 0;  // the kept ids come in input order
                for (std::size_t i = 0; i < n && k < front.size(); ++i)
                    if (scene.polygons[i].id == front[k]) keep[i] = 1, ++k;
                break;
            }
            case Stage::frustum: keep = cull_hierarchy(&hierarchy, scene.camera, {.frustum = true, .candidates = out.kept}).run_to_end().kept; break;
            case Stage::detail:
                keep = cull_hierarchy(&hierarchy, scene.camera,
                                      {.frustum = false, .detail_pixels = o.detail_pixels, .viewport_height = o.viewport.height, .candidates = out.kept})
                           .run_to_end()
                           .kept;
                break;
            case Stage::occluders:
                keep = occlusion_cull(&scene, &hierarchy,
                                      {.max_occluders = o.max_occluders, .candidates = out.kept, .kind = o.occluders, .fusion = o.fusion, .solids = &solids})
                           .run_to_end()
                           .kept;
                break;
            case Stage::portals: {  // what portal_render draws through the PVS and the narrowing frusta
                const CellBsp bsp = build_cell_bsp(*model);
                const Pvs pvs = build_pvs(&*model).run_to_end();
                keep = portal_render(&*model, &bsp, &pvs, model->camera).run_to_end().drawn;
                break;
            }
            case Stage::hiz: {
                HizResult hiz = hiz_render(&scene, &hierarchy, zo, out.kept).run_to_end();
                keep = std::move(hiz.rendered);
                out.frame = std::move(hiz.buffers);
                rendered = true;  // it rendered as it culled: the z-buffer's work is done
                break;
            }
            case Stage::hse: {
                out.frame = cleared_buffers(zo);
                for (std::size_t i = 0; i < n; ++i)
                    if (out.kept[i]) {
                        std::vector<glm::dvec4> clip;
                        for (const auto& v : scene.polygons[i].vertices) clip.push_back(to_clip(scene, v));
                        fill_polygon(out.frame, project_polygon(scene.polygons[i].id, scene.polygons[i].color, std::move(clip), o.viewport),
                                     std::int32_t(i), zo);
                    }
                break;
            }
        }
        for (std::size_t i = 0; i < n; ++i) out.kept[i] = out.kept[i] && keep[i];
        r.milliseconds = ms_since(t);
        r.passed = std::uint32_t(std::count(out.kept.begin(), out.kept.end(), 1));
        r.left_out = r.in - r.passed;
        out.stages.push_back(r);
    }
    return out;
}

}  // namespace hsr::algo
