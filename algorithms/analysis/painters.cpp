// SPDX-License-Identifier: MIT
#include "analysis/painters.h"

#include <chrono>
#include <unordered_map>

#include "bsp/bsp_scene.h"

namespace hsr::analysis {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

}  // namespace

BspPainting paint_bsp(const algo::Scene& scene, algo::SplitterRule splitter, algo::Viewport vp, algo::WorkMeter* meter) {
    std::vector<algo::BspInput> inputs;
    for (const auto& p : scene.polygons) {
        algo::BspInput in{p.id, {}};
        for (const auto& v : p.vertices) in.vertices.emplace_back(v);
        inputs.push_back(std::move(in));
    }
    BspPainting out{algo::Image(vp.width, vp.height, background), {}, 0};
    const auto start = Clock::now();
    // Progress: polygons placed in a node, of the polygons there are (each split adds one)
    double there_are = double(inputs.size());
    if (meter) meter->stage("BSP build", "polygons placed", there_are);
    out.tree = algo::drain(algo::build_bsp(std::move(inputs), {.splitter = splitter}), meter, [&](const algo::BspEvent& e, double& placed) {
        if (std::holds_alternative<algo::PolygonSplit>(e)) meter->set_total(++there_are);
        if (const auto* node = std::get_if<algo::NodeFinished>(&e)) placed += node->coplanar;
    });
    out.build_ms = ms_since(start);
    if (out.tree.bounded) return out;  // a tree a bound cut short is no picture of the scene: nothing is painted
    if (meter) meter->stage("BSP traversal", "polygons in order", double(out.tree.held()));
    const auto order = algo::drain(algo::traverse_bsp(&out.tree, algo::viewpoint_of(scene.camera)), meter,
                                   [](const algo::BspEvent& e, double& drawn) { drawn += std::holds_alternative<algo::PolygonDrawn>(e); });
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

DepthSortPainting paint_depth_sort(const algo::Scene& scene, algo::Viewport vp, algo::WorkMeter* meter) {
    DepthSortPainting out{algo::Image(vp.width, vp.height, background), {}, 0};
    const auto start = Clock::now();
    if (meter) meter->stage("depth sort", "polygons painted", double(scene.polygons.size()));
    out.sorted = algo::drain(algo::depth_sort(algo::sort_polygons(scene)), meter, [](const algo::DepthSortEvent& e, double& painted) {
        painted += std::holds_alternative<algo::PolygonPainted>(e);
    });
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
