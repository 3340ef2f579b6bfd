#include "cli/render_command.h"

#include <chrono>
#include <cstdio>

#include "bsp/bsp_tree.h"
#include "cli/png_io.h"
#include "core/image.h"
#include "scene/load_scene.h"

namespace hsr::viz {
namespace {

std::optional<algo::SplitterRule> splitter_named(const std::string& s) {
    if (s == "first") return algo::SplitterRule::first;
    if (s == "balanced") return algo::SplitterRule::balanced;
    if (s == "fewest-splits") return algo::SplitterRule::fewest_splits;
    if (s == "weighted") return algo::SplitterRule::weighted;
    return std::nullopt;
}

}  // namespace

int run_render(const RenderOptions& o) {
    try {
        algo::Scene scene = algo::load_scene(o.scene);
        if (scene.coordinates != algo::Coordinates::world)
            throw std::runtime_error(o.scene + ": render needs world coordinates");
        if (o.algorithm != "bsp")
            throw std::runtime_error("unknown algorithm \"" + o.algorithm + "\" for render; expected: bsp");
        const auto rule = splitter_named(o.splitter);
        if (!rule) throw std::runtime_error("unknown splitter \"" + o.splitter + "\"; expected first, balanced, fewest-splits or weighted");
        int w = 0, h = 0;
        if (std::sscanf(o.size.c_str(), "%dx%d", &w, &h) != 2 || w < 1 || h < 1 || w > 16384 || h > 16384)
            throw std::runtime_error("--size: expected WxH from 1x1 to 16384x16384, got " + o.size);
        if (o.eye) {
            glm::dvec3 e;
            if (std::sscanf(o.eye->c_str(), "%lf,%lf,%lf", &e.x, &e.y, &e.z) != 3)
                throw std::runtime_error("--eye: expected X,Y,Z, got " + *o.eye);
            scene.camera.eye = e;
        }
        scene.camera.aspect = double(w) / double(h);

        std::vector<algo::BspInput> inputs;
        for (const auto& p : scene.polygons) {
            algo::BspInput in{p.id, {}};
            for (const auto& v : p.vertices) in.vertices.emplace_back(v);
            inputs.push_back(std::move(in));
        }
        const auto start = std::chrono::steady_clock::now();
        const algo::BspTree tree = algo::build_bsp(std::move(inputs), {.splitter = *rule}).run_to_end();
        const double build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        const auto order = algo::traverse_bsp(&tree, scene.camera.eye).run_to_end();

        algo::Image image(w, h, {26, 28, 33});
        const glm::dmat4 vp = algo::view_projection(scene.camera);
        for (algo::BspPolygonId p : order) {  // the painter's order: back to front
            const algo::BspPolygon& poly = tree.polygons[std::size_t(p)];
            algo::Color color{200, 200, 200};
            for (const auto& sp : scene.polygons)
                if (sp.id == poly.source) color = sp.color;
            algo::paint_polygon(image, vp, poly.vertices, std::uint16_t(poly.source), color);
        }
        if (!write_rgb_png(o.out, image)) throw std::runtime_error("cannot write " + o.out);
        if (o.ids && !write_ids_png(*o.ids, image)) throw std::runtime_error("cannot write " + *o.ids);
        std::printf("bsp (%s): %zu polygons in, %zu after %u splits, %zu nodes, depth %u, built in %.3f ms; wrote %s%s%s\n",
                    o.splitter.c_str(), scene.polygons.size(), tree.polygons.size(), tree.splits, tree.nodes.size(),
                    tree.depth, build_ms, o.out.c_str(), o.ids ? " and " : "", o.ids ? o.ids->c_str() : "");
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "hsrviz: %s\n", e.what());
        return 1;
    }
}

}  // namespace hsr::viz
