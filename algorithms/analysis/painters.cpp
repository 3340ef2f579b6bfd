#include "analysis/painters.h"

#include <chrono>
#include <unordered_map>

#include "bsp/bsp_scene.h"

namespace hsr::analysis {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

}  // namespace

BspPainting paint_bsp(const algo::Scene& scene, algo::SplitterRule splitter, algo::Viewport vp) {
    std::vector<algo::BspInput> inputs;
    for (const auto& p : scene.polygons) {
        algo::BspInput in{p.id, {}};
        for (const auto& v : p.vertices) in.vertices.emplace_back(v);
        inputs.push_back(std::move(in));
    }
    BspPainting out{algo::Image(vp.width, vp.height, background), {}, 0};
    const auto start = Clock::now();
    out.tree = algo::build_bsp(std::move(inputs), {.splitter = splitter}).run_to_end();
    out.build_ms = ms_since(start);
    const auto order = algo::traverse_bsp(&out.tree, algo::viewpoint_of(scene.camera)).run_to_end();
    const glm::dmat4 view_projection = algo::view_projection(scene.camera);
    std::unordered_map<algo::SceneId, algo::Color> color_of;  // by the scene's id: a lookup per fragment, not a scan
    for (const auto& sp : scene.polygons) color_of.emplace(sp.id, sp.color);
    for (algo::BspPolygonId p : order) {  // the painter's order: back to front
        const algo::BspPolygon& poly = out.tree.polygons[std::size_t(p)];
        const auto c = color_of.find(poly.source);
        algo::paint_polygon(out.image, view_projection, poly.vertices, poly.source, c != color_of.end() ? c->second : algo::Color{200, 200, 200});
    }
    return out;
}

DepthSortPainting paint_depth_sort(const algo::Scene& scene, algo::Viewport vp) {
    DepthSortPainting out{algo::Image(vp.width, vp.height, background), {}, 0};
    const auto start = Clock::now();
    out.sorted = algo::depth_sort(algo::sort_polygons(scene)).run_to_end();
    out.sort_ms = ms_since(start);
    for (std::uint32_t i : out.sorted.order) {  // back to front, each polygon in normalised device coordinates
        std::vector<glm::dvec4> ndc;
        for (const auto& v : out.sorted.polygons[i].vertices) ndc.emplace_back(v, 1.0);
        algo::paint_clip_polygon(out.image, std::move(ndc), out.sorted.polygons[i].id, out.sorted.polygons[i].color,
                                 out.sorted.polygons[i].opacity);
    }
    return out;
}

}  // namespace hsr::analysis
