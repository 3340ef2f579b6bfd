// SPDX-License-Identifier: MIT
// Practice for hierarchical visibility with a Z-pyramid, on fat pixels: rectangles facing an orthographic camera,
// each at one depth, a large one near the eye and small ones behind and beside it, in an octree walked front to back.
// When a node comes up, is its box hidden behind everything already drawn over its footprint (isOccluded), or are its
// primitives rendered? Every answer is a HizNodeTested event of the Hi-Z lesson's own machine on the scene.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "culling/hierarchy.h"
#include "culling/hiz.h"
#include "state/practice/pixel_triangles.h"
#include "zbuffer/zbuffer_fill.h"
#include "core/okabe_ito.h"

namespace hsr::viz::practice {
namespace {

struct Rect {
    int x0, y0, x1, y1;  // pixels [x0, x1) × [y0, y1)
    double depth;
};

// What the question says, each template once (the catalogues' [exercise.hiz] translate them).
namespace say {
using algo::Saying;
constexpr Saying occluded_asked{"hiz.occluded",
                                "Hierarchical visibility with a Z-pyramid on a 32 × 24 grid (x to the right, y down; depth is the "
                                "distance from the eye, the background at depth 10). Drawn so far over the footprint below: "
                                "{drawn}. Octree node {node} comes up: its box's footprint covers pixels x {x0}…{x1}, y {y0}…{y1}, "
                                "and its nearest depth is {near}. Is it occluded?"};
constexpr Saying rectangle{"hiz.rectangle", "rectangle {number}, pixels x {x0}…{x1}, y {y0}…{y1}, depth {depth}"};
constexpr Saying nothing{"hiz.nothing", "nothing"};
constexpr Saying occluded{"hiz.occluded_choice", "occluded: it and everything below it are skipped"};
constexpr Saying not_occluded{"hiz.not_occluded", "not occluded: its primitives are rendered"};
constexpr Saying all[] = {occluded_asked, rectangle, nothing, occluded, not_occluded};
}  // namespace say

// A rectangle of pixels as the question names it: its first and last pixel along x and along y.
std::vector<algo::NamedValue> pixels(int x0, int y0, int x1, int y1) {
    return {{"x0", std::to_string(x0)}, {"x1", std::to_string(x1 - 1)}, {"y0", std::to_string(y0)}, {"y1", std::to_string(y1 - 1)}};
}

// The occluder: a large rectangle at depth 2 or 3; behind it and beside it, clusters of small rectangles at depths
// 5 … 9 (hard: as near as a few tenths behind the occluder). Clusters make the octree split their region into cells
// small enough to hide behind the occluder (scattered rectangles give only large cells that peek out).
std::vector<Rect> draw_rects(Dice& d, Level l) {
    std::vector<Rect> r;
    const auto between = [&d](int lo, int hi) { return lo + d.below(hi - lo + 1); };
    const int w = between(14, 20), h = between(10, 14), x0 = between(2, 30 - w), y0 = between(2, 22 - h);
    r.push_back({x0, y0, x0 + w, y0 + h, d.grid(2, 3, 1)});
    const int clusters = l == Level::easy ? 2 : 3;
    for (int c = 0; c < clusters; ++c) {
        // the first cluster behind the occluder's middle, the others anywhere
        const int cx = c == 0 ? x0 + w / 2 - 2 : between(1, 27), cy = c == 0 ? y0 + h / 2 - 2 : between(1, 19);
        const double cz = l == Level::hard && d.coin() ? r[0].depth + 1 : d.grid(5, 8, 0.5);
        for (int k = 0; k < 5; ++k) {
            const int sw = between(1, 2), sh = between(1, 2), sx = cx + between(0, 4 - sw), sy = cy + between(0, 4 - sh);
            r.push_back({sx, sy, sx + sw, sy + sh, cz + d.grid(0, 1, 0.25)});
        }
    }
    return r;
}

algo::Scene scene_of(const std::vector<Rect>& rects) {
    algo::Scene scene = pixel_grid_scene("rectangles behind an occluder");
    scene.camera.aspect = double(pixel_grid.width) / pixel_grid.height;
    for (std::size_t k = 0; k < rects.size(); ++k) {
        const Rect& r = rects[k];
        const algo::Color colour = k == 0 ? algo::okabe_ito::as<algo::Color>(algo::okabe_ito::orange) : algo::okabe_ito::as<algo::Color>(algo::okabe_ito::sky_blue);
        algo::ScenePolygon p{algo::SceneId(k + 1), colour, {}};
        for (const glm::dvec2 c : {glm::dvec2(r.x0, r.y1), glm::dvec2(r.x1, r.y1), glm::dvec2(r.x1, r.y0), glm::dvec2(r.x0, r.y0)})
            p.vertices.push_back(pixel_point(c, r.depth));
        scene.polygons.push_back(p);
    }
    return scene;
}


std::optional<Exercise> occlusion_exercise(Dice& d, Level l) {
    const std::vector<Rect> rects = draw_rects(d, l);
    algo::Scene scene = scene_of(rects);
    // as the Hi-Z lesson does: an octree over the polygons' boxes, a 24-bit buffer on the lesson's grid
    const algo::Hierarchy tree = algo::build_hierarchy(algo::polygon_boxes(scene), {.kind = algo::HierarchyKind::octree}).run_to_end();
    const algo::ZBufferOptions options = algo::zbuffer_options(scene, pixel_grid, algo::DepthFormat::int24, algo::EventDetail::polygon);
    std::vector<algo::HizEvent> events;
    auto machine = algo::hiz_render(&scene, &tree, options);
    while (const algo::HizEvent* e = machine.next()) events.push_back(*e);
    // the nodes a student can decide from what is drawn: in view, in front of the eye, some rectangle already drawn,
    // and a nearest depth no hair from a drawn rectangle's; an outcome first, then a node
    std::vector<std::size_t> drawn;  // rectangles drawn so far
    std::vector<std::pair<std::size_t, std::vector<std::size_t>>> by_outcome[2];  // step, rectangles drawn before it
    for (std::size_t step = 0; step < events.size(); ++step) {
        const auto* t = std::get_if<algo::HizNodeTested>(&events[step]);
        if (!t) continue;
        const algo::BoxOnScreen on_screen = algo::box_on_screen(tree.nodes[t->node].box, scene, options);
        const double near_depth = 10 - tree.nodes[t->node].box.hi.z;  // the eye at z = 10 looks down −z
        const bool fair = t->outcome != algo::HizOutcome::outside_frustum && !on_screen.reaches_eye && !drawn.empty() &&
                          std::none_of(drawn.begin(), drawn.end(), [&](std::size_t k) { return std::abs(rects[k].depth - near_depth) < 0.05; });
        if (fair) by_outcome[t->outcome == algo::HizOutcome::occluded ? 0 : 1].emplace_back(step, drawn);
        if (t->outcome == algo::HizOutcome::rendered)
            for (std::uint32_t p : tree.nodes[t->node].primitives) drawn.push_back(p);
    }
    // most draws hide no node a student can decide: draw again three times in four, so that both answers come up
    if (by_outcome[0].empty() && d.below(4) != 0) return std::nullopt;
    std::vector<const std::vector<std::pair<std::size_t, std::vector<std::size_t>>>*> present;
    for (const auto& steps : by_outcome)
        if (!steps.empty()) present.push_back(&steps);
    if (present.empty()) return std::nullopt;
    const auto& pick = *present[std::size_t(d.below(int(present.size())))];
    const auto& [step, before] = pick[std::size_t(d.below(int(pick.size())))];
    const auto& tested = std::get<algo::HizNodeTested>(events[step]);
    const algo::PixelRect f{std::max(tested.footprint.x0, 0), std::max(tested.footprint.y0, 0),
                            std::min(tested.footprint.x1, pixel_grid.width), std::min(tested.footprint.y1, pixel_grid.height)};
    if (f.empty()) return std::nullopt;
    const double near_depth = 10 - tree.nodes[tested.node].box.hi.z;
    Exercise e;
    std::vector<Wording> drawn_words;
    nlohmann::json drawn_json = nlohmann::json::array();
    for (std::size_t k : before) {
        const Rect& r = rects[k];
        if (r.x1 <= f.x0 || f.x1 <= r.x0 || r.y1 <= f.y0 || f.y1 <= r.y0) continue;  // not over the footprint
        std::vector<algo::NamedValue> values = pixels(r.x0, r.y0, r.x1, r.y1);
        values.emplace_back("number", std::to_string(k + 1));
        values.emplace_back("depth", number_text(r.depth));
        drawn_words.push_back(Wording(say::rectangle, std::move(values)));
        drawn_json.push_back({{"pixels", {r.x0, r.y0, r.x1, r.y1}}, {"depth", r.depth}});
    }
    std::vector<algo::NamedValue> values = pixels(f.x0, f.y0, f.x1, f.y1);
    values.emplace_back("node", std::to_string(tested.node));
    values.emplace_back("near", number_text(near_depth));
    if (drawn_words.empty()) drawn_words.push_back(Wording(say::nothing));
    e.ask(Wording(say::occluded_asked, std::move(values), {{"drawn", std::move(drawn_words)}}));
    e.offer({Wording(say::occluded), Wording(say::not_occluded)}, tested.outcome == algo::HizOutcome::occluded ? 0 : 1);
    e.deciding = algo::describe(events[step]);
    e.deciding_step = step;
    e.given = {{"kind", "hiz_occluded"}, {"drawn", drawn_json}, {"footprint", {f.x0, f.y0, f.x1, f.y1}}, {"near", near_depth}};
    e.scene = std::move(scene);
    e.algorithm = "cull_hiz";
    e.cull = "hiz";  // the Z-pyramid alone: no earlier stage leaves a rectangle out
    return e;
}

}  // namespace

std::vector<Topic> hiz_topics() {
    return {{"hiz", "Hi-Z: is a node hidden behind what is drawn?", {"cull_hiz"}, [](Draw draw) {
                 Dice d(draw.seed);
                 return occlusion_exercise(d, draw.level);
             },
             {say::all}}};
}

}  // namespace hsr::viz::practice
