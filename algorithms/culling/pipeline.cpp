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

PreparedScene prepare_scene(const Scene& given, const PipelineOptions& o) {
    const auto t = Clock::now();
    PreparedScene p;
    // A floor plan plays as its rooms' walls, floors and objects
    if (!given.floor_plan.cells.empty()) p.model = cell_model(given);
    p.scene = p.model ? model_scene(*p.model) : given;
    const auto wanted = [&](Stage s) { return std::find(o.stages.begin(), o.stages.end(), s) != o.stages.end(); };
    p.hierarchy = build_hierarchy(polygon_boxes(p.scene), {.kind = o.hierarchy}).run_to_end();
    // and the objects that are solid occluders, found once like the hierarchy
    if (o.occluders == OccluderKind::solid && wanted(Stage::occluders)) p.solids = convex_solids(p.scene);
    if (p.model && wanted(Stage::portals)) p.cell_bsp = build_cell_bsp(*p.model), p.pvs = build_pvs(&*p.model).run_to_end();
    p.milliseconds = ms_since(t);
    return p;
}

PipelineResult run_pipeline(const Scene& given, const PipelineOptions& o) {
    PreparedScene prepared = prepare_scene(given, o);
    const Camera camera = prepared.scene.camera;
    return run_frame(prepared, camera, o);
}

std::vector<std::uint8_t> seen_in(const PipelineResult& frame, std::size_t polygons) {
    std::vector<std::uint8_t> seen(polygons, 0);
    for (const std::int32_t p : frame.frame.polygon)
        if (p >= 0 && std::size_t(p) < polygons) seen[std::size_t(p)] = 1;
    return seen;
}

PipelineResult run_frame(PreparedScene& prepared, const Camera& camera, const PipelineOptions& o, const std::vector<std::uint8_t>& seen_before) {
    prepared.scene.camera = camera;
    if (prepared.model) prepared.model->camera = camera;
    const Scene& scene = prepared.scene;
    const Hierarchy& hierarchy = prepared.hierarchy;
    const std::size_t n = scene.polygons.size();
    const auto wanted = [&](Stage s) { return s == Stage::hse || std::find(o.stages.begin(), o.stages.end(), s) != o.stages.end(); };
    PipelineResult out;
    out.kept.assign(n, 1);
    const ZBufferOptions zo = zbuffer_options(scene, o.viewport, o.format, EventDetail::polygon);
    out.hierarchy_milliseconds = prepared.milliseconds;
    bool rendered = false;
    for (const Stage stage : all_stages) {
        StageReport r{stage};
        r.in = std::uint32_t(std::count(out.kept.begin(), out.kept.end(), 1));
        r.candidates = out.kept;
        if (!wanted(stage) || (stage == Stage::hse && rendered) || (stage == Stage::portals && !prepared.pvs)) {
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
                                      {.max_occluders = o.max_occluders, .candidates = out.kept, .kind = o.occluders, .fusion = o.fusion,
                                       .solids = &prepared.solids})
                           .run_to_end()
                           .kept;
                break;
            case Stage::portals:  // what portal_render draws through the PVS and the narrowing frusta
                keep = portal_render(&*prepared.model, &*prepared.cell_bsp, &*prepared.pvs, camera).run_to_end().drawn;
                break;
            case Stage::hiz: {
                HizResult hiz = hiz_render(&scene, &hierarchy, zo, out.kept, seen_before).run_to_end();
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
