// SPDX-License-Identifier: MIT
#include "renderers.h"

#include "analysis/painters.h"
#include "depth_sort/front_to_back.h"
#include "culling/pipeline.h"
#include "zbuffer/classic_scanline.h"
#include "zbuffer/scanline.h"
#include "zbuffer/zbuffer_fill.h"

namespace hsr::test {

using algo::DepthFormat;
using algo::SceneId;

namespace {

Drawn zbuffer(const algo::Scene& s, algo::Viewport vp, DepthFormat f) {
    algo::FrameDepth d =
        algo::zbuffer_fill(algo::project_polygons(s, vp), algo::zbuffer_options(s, vp, f, algo::EventDetail::polygon)).run_to_end();
    return {std::move(d.image.ids), {}, d.bounded};
}

Drawn scan_line(const algo::Scene& s, algo::Viewport vp, DepthFormat f) {
    algo::ScanLineOptions o = algo::scan_line_options(s, vp, f);
    o.tell_crossings = false;
    algo::FrameDepth d = algo::scan_line(algo::project_polygons(s, vp), o).run_to_end();
    return {std::move(d.image.ids), {}, d.bounded};
}

// The Brown notes' classic form: no z-buffer, the planes compared where spans begin (exact doubles: its ties are
// the planes' own, which the int24 tie rule covers).
Drawn classic_scan_line(const algo::Scene& s, algo::Viewport vp) {
    algo::ScanLineOptions o = algo::scan_line_options(s, vp, DepthFormat::int24);
    o.tell_crossings = false;
    algo::FrameDepth d = algo::classic_scan_line(algo::project_polygons(s, vp), {.line = o}).run_to_end();
    return {std::move(d.image.ids), {}, d.bounded};
}

Drawn bsp(const algo::Scene& s, algo::Viewport vp, algo::SplitterRule rule) {
    analysis::BspPainting p = analysis::paint_bsp(s, rule, vp);
    Drawn d{std::move(p.image.ids), {}, p.tree.bounded};
    const glm::dmat4 m = algo::view_projection(s.camera);
    for (const algo::BspPolygon& part : p.tree.polygons) {
        std::vector<glm::dvec4> clip;
        for (const algo::Vec3& v : part.vertices) clip.push_back(m * glm::dvec4(v, 1.0));
        add_outline(d.parts, SceneId(part.source), clip, vp);
    }
    return d;
}

Drawn depth_sort(const algo::Scene& s, algo::Viewport vp) {
    analysis::DepthSortPainting p = analysis::paint_depth_sort(s, vp);
    Drawn d{std::move(p.image.ids), {}, p.sorted.bounded};
    for (const algo::SortPolygon& part : p.sorted.polygons) {
        std::vector<glm::dvec4> ndc;
        for (const algo::Vec3& v : part.vertices) ndc.emplace_back(v, 1.0);
        add_outline(d.parts, part.id, ndc, vp);
    }
    return d;
}

// The same sort displayed front to back (the notes' optimisation): each pixel written once, by the nearest.
Drawn depth_sort_front_to_back(const algo::Scene& s, algo::Viewport vp) {
    const algo::DepthSortResult sorted = algo::depth_sort(algo::sort_polygons(s)).run_to_end();
    Drawn d{algo::display_front_to_back(sorted.polygons, sorted.order, vp).run_to_end().image.ids, {}, sorted.bounded};
    for (const algo::SortPolygon& part : sorted.polygons) {
        std::vector<glm::dvec4> ndc;
        for (const algo::Vec3& v : part.vertices) ndc.emplace_back(v, 1.0);
        add_outline(d.parts, part.id, ndc, vp);
    }
    return d;
}

// The culling pipeline's conservative stages, then its z-buffer: what they leave out must not change the picture.
Drawn culled(const algo::Scene& s, algo::Viewport vp) {
    algo::PipelineResult r = algo::run_pipeline(s, {.stages = algo::parse_stages("frustum,occluders,hiz"), .viewport = vp});
    return {std::move(r.frame.image.ids), {}, r.frame.bounded};
}

}  // namespace

Drawn ray_cast(const algo::Scene& s, algo::Viewport vp, algo::Acceleration a) {
    algo::RayCastResult r = algo::ray_cast(s, {.viewport = vp, .acceleration = a, .detail = algo::RayDetail::ray}).run_to_end();
    return {std::move(r.image.ids), {}, r.bounded};
}

std::vector<Renderer> cpu_renderers() {
    using F = DepthFormat;
    std::vector<Renderer> r;
    for (const F f : {F::int16, F::int24, F::int32, F::float32, F::float32_reversed, F::linear24})
        r.push_back({"zbuffer " + std::string(algo::format_id(f)), {f}, [f](const auto& s, auto vp) { return zbuffer(s, vp, f); }});
    for (const F f : {F::int16, F::int24, F::int32, F::float32, F::float32_reversed, F::linear24})
        r.push_back({"scanline " + std::string(algo::format_id(f)), {f}, [f](const auto& s, auto vp) { return scan_line(s, vp, f); }});
    r.push_back({"scanline classic", {}, classic_scan_line});
    for (const algo::Acceleration a : {algo::Acceleration::grid, algo::Acceleration::octree, algo::Acceleration::bvh})
        r.push_back({"raycast " + std::string(algo::to_string(a)), {}, [a](const auto& s, auto vp) { return ray_cast(s, vp, a); }});
    using R = algo::SplitterRule;
    for (const auto& [rule, name] : {std::pair{R::first, "first"}, std::pair{R::balanced, "balanced"},
                                     std::pair{R::fewest_splits, "fewest-splits"}, std::pair{R::weighted, "weighted"}}) {
        const R rr = rule;
        r.push_back({std::string("bsp ") + name, {}, [rr](const auto& s, auto vp) { return bsp(s, vp, rr); }});
    }
    r.push_back({"depth-sort", {}, depth_sort});
    r.push_back({"depth-sort front to back", {}, depth_sort_front_to_back});
    r.push_back({"culling frustum,occluders,hiz", {F::int24}, culled});
    return r;
}

}  // namespace hsr::test
