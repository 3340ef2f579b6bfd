// SPDX-License-Identifier: MIT
// Practice for occluding pairs: two points in eye space (the eye at the origin looking down −z), in perspective or
// orthographic projection; which of them occludes the other, or neither? One of them a multiple of the other (one
// projection ray in perspective), or with the other's x and y (one ray only in orthographic projection), or just off
// a ray, or anywhere. The answer is the perspective-transform machine's comparison of the pair.
#include <string>

#include "perspective/perspective_transform.h"
#include "state/practice/practice.h"
#include "state/practice/practice_random.h"
#include "core/okabe_ito.h"

namespace hsr::viz::practice {
namespace {

// What the questions say, each template once (the catalogues' [exercise.occluding] translate them).
namespace say {
using algo::Saying;
constexpr Saying pair{"occluding.pair",
                      "Eye space, the eye at the origin looking down −z, {projection} projection. P0 = {a}, P1 = {b}. Two points on one "
                      "projection ray form an occluding pair, and the nearer occludes the other. Which point occludes the other?"};
constexpr Saying perspective{"occluding.perspective", "perspective"};
constexpr Saying orthographic{"occluding.orthographic", "orthographic"};
constexpr Saying neither{"occluding.neither", "neither: not on one projection ray"};
constexpr Saying all[] = {pair, perspective, orthographic, neither};
}  // namespace say

std::string point_text(algo::Vec3 p) { return "(" + number_text(p.x) + ", " + number_text(p.y) + ", " + number_text(p.z) + ")"; }

std::optional<Exercise> occluding_exercise(Dice& d, Level level) {
    const bool perspective = level == Level::easy || d.coin();
    algo::Vec3 a(d.grid(-1.5, 1.5, 0.5), d.grid(-1, 1, 0.5), -d.grid(2, 4, 1));
    const double k = d.pick(std::vector<double>{0.5, 2, 3});
    algo::Vec3 b;
    switch (d.below(level == Level::hard ? 4 : 3)) {
        case 0: b = perspective ? a * k : algo::Vec3(a.x, a.y, a.z * k); break;   // one ray
        case 1: b = perspective ? algo::Vec3(a.x, a.y, a.z * k) : a * k; break;   // the other projection's ray
        case 2: b = algo::Vec3(d.grid(-1.5, 1.5, 0.5), d.grid(-1, 1, 0.5), -d.grid(2, 6, 1)); break;  // anywhere
        default: b = a * k + algo::Vec3(0.125, 0, 0);  // just off a perspective ray
    }
    if (d.coin()) std::swap(a, b);  // … so the nearer is as often P1 as P0
    if (a == b) return std::nullopt;
    algo::Scene scene;
    scene.name = "practice points";
    scene.camera.eye = {0, 0, 0}, scene.camera.target = {0, 0, -1}, scene.camera.near = 1, scene.camera.far = 16;  // the farthest point is at z = −12
    if (!perspective) {
        scene.camera.projection = algo::Projection::orthographic;
        scene.camera.box[0] = -2.5, scene.camera.box[1] = 2.5, scene.camera.box[2] = -2.5, scene.camera.box[3] = 2.5;
    }
    scene.points.push_back({1, algo::okabe_ito::as<algo::Color>(algo::okabe_ito::orange), glm::dvec4(a, 1)});
    scene.points.push_back({2, algo::okabe_ito::as<algo::Color>(algo::okabe_ito::sky_blue), glm::dvec4(b, 1)});
    std::vector<algo::TransformEvent> events;
    auto machine = algo::perspective_transform(scene);
    while (const algo::TransformEvent* e = machine.next()) events.push_back(*e);
    Exercise x;
    for (std::size_t k2 = 0; k2 < events.size(); ++k2)
        if (const auto* c = std::get_if<algo::PairCompared>(&events[k2])) {
            if (c->same_after && c->nearer < 0) return std::nullopt;  // equal z′: no question to ask
            x.offer({Wording::as_is("P0"), Wording::as_is("P1"), Wording(say::neither)}, !c->same_after ? 2 : std::size_t(c->nearer));
            x.deciding = algo::describe(events[k2]);
            x.deciding_step = k2;
        }
    if (x.deciding.empty()) return std::nullopt;
    x.ask(Wording(say::pair, {{"a", point_text(a)}, {"b", point_text(b)}},
                  {{"projection", {Wording(perspective ? say::perspective : say::orthographic)}}}));
    x.given = {{"kind", "occluding_pair"}, {"a", {a.x, a.y, a.z}}, {"b", {b.x, b.y, b.z}}, {"perspective", perspective}};
    x.scene = std::move(scene);
    x.algorithm = "perspective_transform";
    return x;
}

}  // namespace

std::vector<Topic> perspective_topics() {
    return {{"occluding_pairs", "Occluding pairs: which point occludes the other?", {"perspective_transform"}, [](Draw draw) {
                 Dice d(draw.seed);
                 return occluding_exercise(d, draw.level);
             },
             {say::all}}};
}

}  // namespace hsr::viz::practice
