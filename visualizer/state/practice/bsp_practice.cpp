// SPDX-License-Identifier: MIT
// Practice for BSP trees, on the classroom's picture: walls (segments) in a floor plan. BuildBSP with the first wall
// of each list as the node's splitter: where does a wall lie, seen from the root's line? DisplayBSP from an eye: on
// which side of the root's line is the eye, so which subtree is painted first? Every answer is an event of the
// machine the BSP lessons play (build, then traversal) on the exercise's own walls.
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "bsp/bsp_events.h"
#include "bsp/bsp_scene.h"
#include "state/practice/practice.h"
#include "state/practice/practice_random.h"
#include "core/okabe_ito.h"

namespace hsr::viz::practice {
namespace {

using glm::dvec2;

struct Wall {
    dvec2 a, b;
};

std::string point_text(dvec2 p) {
    char text[64];
    std::snprintf(text, sizeof text, "(%g, %g)", p.x, p.y);
    std::string t = text;
    for (std::size_t at = t.find('-'); at != std::string::npos; at = t.find('-', at)) t.replace(at, 1, "−");
    return t;
}
// What the questions say, each template once (the catalogues' [exercise.bsp] translate them).
namespace say {
using algo::Saying;
constexpr Saying wall{"bsp.wall", "wall {number} from {a} to {b}"};
constexpr Saying wall_side{"bsp.wall_side",
                           "BuildBSP makes the first wall of each list its node's splitter. The root's is {root} (its front "
                           "is the left of a → b, as you walk from a to b). Where does {wall} lie, seen from wall 1's line?"};
constexpr Saying front{"bsp.front", "front"};
constexpr Saying back{"bsp.back", "back"};
constexpr Saying spanning{"bsp.spanning", "spanning"};
constexpr Saying coplanar{"bsp.coplanar", "coplanar"};
constexpr Saying eye_side{"bsp.eye_side",
                          "DisplayBSP paints back to front from the eye at {eye}. The root's splitter is {root} (its front is "
                          "the left of a → b, as you walk from a to b). Where is the eye, seen from wall 1's line?"};
constexpr Saying eye_in_front{"bsp.eye_in_front", "in front: its back subtree is painted first"};
constexpr Saying eye_behind{"bsp.eye_behind", "behind: its front subtree is painted first"};
constexpr Saying all[] = {wall, wall_side, front, back, spanning, coplanar, eye_side, eye_in_front, eye_behind};
}  // namespace say

Wording wall_text(const std::vector<Wall>& walls, std::size_t k) {
    return Wording(say::wall, {{"number", std::to_string(k + 1)}, {"a", point_text(walls[k].a)}, {"b", point_text(walls[k].b)}});
}
nlohmann::json numbers(dvec2 p) { return nlohmann::json::array({p.x, p.y}); }

// The signed distance of p from the line of w, positive on its front: the left of a → b (the machine's normal).
double side_of(const Wall& w, dvec2 p) {
    const dvec2 d = w.b - w.a;
    return (d.x * (p.y - w.a.y) - d.y * (p.x - w.a.x)) / glm::length(d);
}

// A reading margin: no end of a wall and no eye closer than this to another wall's line, where the tolerance of
// the machine's classification (and a student's eye) would decide.
constexpr double margin = 0.05;

// Walls on a grid of whole units (halves at the hard level, with ends a tenth or two from another wall's line)
// in [−5, 5]², and an eye among them.
std::optional<std::pair<std::vector<Wall>, dvec2>> draw(Dice& d, Level l) {
    const int count = l == Level::easy ? 4 : l == Level::medium ? 5 : 6;
    const double step = l == Level::hard ? 0.5 : 1;
    auto point = [&] { return dvec2(d.grid(-5 / step, 5 / step, 1) * step, d.grid(-5 / step, 5 / step, 1) * step); };
    std::vector<Wall> walls;
    for (int k = 0; k < count; ++k) {
        Wall w{point(), point()};
        if (glm::length(w.b - w.a) < 1.5) return std::nullopt;
        walls.push_back(w);
    }
    if (l == Level::hard) {  // one wall's end pulled to a tenth or two from the root's line, on a side the dice choose
        Wall& w = walls[std::size_t(1 + d.below(count - 1))];
        const dvec2 d0 = walls[0].b - walls[0].a, n = dvec2(-d0.y, d0.x) / glm::length(d0);
        w.b -= n * side_of(walls[0], w.b);
        w.b += n * (d.coin() ? 1.0 : -1.0) * (d.grid(1, 2, 1) / 10);
        w.b = glm::round(w.b * 1000.0) / 1000.0;
    }
    const dvec2 eye = point();
    for (std::size_t i = 0; i < walls.size(); ++i) {
        if (std::abs(side_of(walls[i], eye)) < margin) return std::nullopt;
        for (std::size_t j = 0; j < walls.size(); ++j)
            if (i != j && (std::abs(side_of(walls[i], walls[j].a)) < margin || std::abs(side_of(walls[i], walls[j].b)) < margin))
                return std::nullopt;
    }
    return std::pair{walls, eye};
}

algo::Scene scene_of(const std::vector<Wall>& walls, dvec2 eye) {
    static const algo::Color colours[] = {algo::okabe_ito::as<algo::Color>(algo::okabe_ito::sky_blue), algo::okabe_ito::as<algo::Color>(algo::okabe_ito::bluish_green), algo::okabe_ito::as<algo::Color>(algo::okabe_ito::orange), algo::okabe_ito::as<algo::Color>(algo::okabe_ito::reddish_purple), algo::okabe_ito::as<algo::Color>(algo::okabe_ito::vermillion), algo::okabe_ito::as<algo::Color>(algo::okabe_ito::yellow)};
    algo::Scene scene;
    scene.name = "walls in a floor plan";
    scene.camera.eye = {eye.x, eye.y, 0};
    scene.camera.target = {0, 0, 0};
    if (glm::length(eye) < 0.5) scene.camera.target = {1, 1, 0};
    scene.camera.up = {0, 0, 1};
    scene.camera.near = 0.1;
    scene.camera.far = 40;
    for (std::size_t k = 0; k < walls.size(); ++k)
        scene.segments.push_back({algo::SceneId(k + 1), colours[k % 6], {walls[k].a, 0, 1}, {walls[k].b, 0, 1}});
    return scene;
}

// The walls before any split are named by their ids, 1 … n, as the view names them.
std::string original_name(algo::BspPolygonId k) { return std::to_string(k + 1); }

std::vector<algo::BspEvent> play(const algo::Scene& scene) {
    std::vector<algo::BspEvent> events;
    auto machine = algo::bsp_scene(algo::bsp_job(scene, algo::SplitterRule::first));
    while (const algo::BspEvent* e = machine.next()) events.push_back(*e);
    return events;
}

nlohmann::json given(const std::vector<Wall>& walls, dvec2 eye, const char* kind, std::size_t asked) {
    nlohmann::json w = nlohmann::json::array();
    for (const Wall& wall : walls) w.push_back({numbers(wall.a), numbers(wall.b)});
    return {{"kind", kind}, {"walls", w}, {"eye", numbers(eye)}, {"wall", asked + 1}};
}


std::optional<Exercise> build_exercise(Dice& d, Level l) {
    const auto drawn = draw(d, l);
    if (!drawn) return std::nullopt;
    const auto& [walls, eye] = *drawn;
    const std::size_t asked = std::size_t(1 + d.below(int(walls.size()) - 1));
    algo::Scene scene = scene_of(walls, eye);
    const std::vector<algo::BspEvent> events = play(scene);
    for (std::size_t step = 0; step < events.size(); ++step) {
        const auto* c = std::get_if<algo::PolygonClassified>(&events[step]);
        if (!c || c->node != 0 || c->polygon != algo::BspPolygonId(asked)) continue;
        Exercise x;
        x.ask(Wording(say::wall_side, {}, {{"root", {wall_text(walls, 0)}}, {"wall", {wall_text(walls, asked)}}}));
        const std::size_t side = c->side == algo::PolygonSide::front      ? 0
                                 : c->side == algo::PolygonSide::back     ? 1
                                 : c->side == algo::PolygonSide::spanning ? 2
                                                                          : 3;
        x.offer({Wording(say::front), Wording(say::back), Wording(say::spanning), Wording(say::coplanar)}, side);
        x.deciding = algo::describe(events[step], original_name);
        x.deciding_step = step;
        x.given = given(walls, eye, "wall_side", asked);
        x.scene = std::move(scene);
        x.algorithm = "bsp_build";
        return x;
    }
    return std::nullopt;
}


std::optional<Exercise> traversal_exercise(Dice& d, Level l) {
    const auto drawn = draw(d, l);
    if (!drawn) return std::nullopt;
    const auto& [walls, eye] = *drawn;
    algo::Scene scene = scene_of(walls, eye);
    const std::vector<algo::BspEvent> events = play(scene);
    for (std::size_t step = 0; step < events.size(); ++step) {
        const auto* c = std::get_if<algo::EyeClassified>(&events[step]);
        if (!c || c->node != 0 || c->side == algo::Side::on) continue;
        Exercise x;
        x.ask(Wording(say::eye_side, {{"eye", point_text(eye)}}, {{"root", {wall_text(walls, 0)}}}));
        x.offer({Wording(say::eye_in_front), Wording(say::eye_behind)}, c->side == algo::Side::front ? 0 : 1);
        x.deciding = algo::describe(events[step], original_name);
        x.deciding_step = step;
        x.given = given(walls, eye, "eye_side", 0);
        x.scene = std::move(scene);
        x.algorithm = "bsp_traversal";
        return x;
    }
    return std::nullopt;
}

}  // namespace

std::vector<Topic> bsp_topics() {
    return {{"bsp", "BSP trees: building and painting back to front", {"bsp_build", "bsp_traversal"}, [](Draw draw) {
                 Dice d(draw.seed);
                 return d.coin() ? build_exercise(d, draw.level) : traversal_exercise(d, draw.level);
             },
             {say::all}}};
}

}  // namespace hsr::viz::practice
