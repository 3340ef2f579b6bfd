// SPDX-License-Identifier: MIT
// Practice for back-face culling: is a triangle front- or back-facing from an eye (by the view-vector test or the
// plane-equation test of the notes), and how far is the eye from its plane (N · eye + D with N of unit length)?
// Every answer is the FaceTested event of the machine run on the exercise's triangle and eye.
#include <cmath>
#include <cstdio>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "culling/backface.h"
#include "state/practice/practice.h"
#include "state/practice/practice_random.h"
#include "core/okabe_ito.h"

namespace hsr::viz::practice {
namespace {

using algo::Vec3;

std::string point_text(const Vec3& p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%g, %g, %g)", p.x, p.y, p.z);
    std::string t = text;
    for (std::size_t at = t.find('-'); at != std::string::npos; at = t.find('-', at)) t.replace(at, 1, "−");
    return t;
}
nlohmann::json numbers(const Vec3& p) { return nlohmann::json::array({p.x, p.y, p.z}); }

Vec3 draw_corner(Dice& d, Level l) {
    const double step = l == Level::easy ? 1 : 0.5;
    return {d.grid(-3, 3, 1) * step, d.grid(-3, 3, 1) * step, d.grid(-3, 3, 1) * step};
}

struct Drawn {
    Vec3 a, b, c, eye;
};

// A triangle with room to see its winding, and an eye on a grid (easy, medium) or a few hundredths from the
// triangle's plane (hard: the sign is all that is left to read).
std::optional<Drawn> draw(Dice& d, Level l) {
    Drawn t{draw_corner(d, l), draw_corner(d, l), draw_corner(d, l), {}};
    const Vec3 n = glm::cross(t.b - t.a, t.c - t.a);
    if (glm::length(n) < 0.5) return std::nullopt;
    if (l == Level::hard) {
        const double u = d.grid(0, 10, 1) / 10, v = d.grid(0, 10, 1) / 10, off = d.grid(1, 9, 1) / 100 * (d.coin() ? 1 : -1);
        t.eye = t.a + u * (t.b - t.a) + v * (t.c - t.a) + off * glm::normalize(n);
        t.eye = glm::round(t.eye * 1000.0) / 1000.0;  // three decimals, as the question prints it
    } else {
        const double step = l == Level::easy ? 1 : 0.5;
        t.eye = {d.grid(-10, 10, 1) * step, d.grid(-10, 10, 1) * step, d.grid(-10, 10, 1) * step};
    }
    if (std::abs(glm::dot(t.eye - t.a, glm::normalize(n))) < 0.005) return std::nullopt;  // edge-on, or nearly
    if (glm::length(t.eye - (t.a + t.b + t.c) / 3.0) < 0.5) return std::nullopt;
    return t;
}

// The exercise's scene as the window plays it: the triangle, and a camera at the eye looking at it.
algo::Scene scene_of(const Drawn& t) {
    algo::Scene scene;
    scene.name = "a triangle and an eye";
    scene.camera.eye = t.eye;
    scene.camera.target = (t.a + t.b + t.c) / 3.0;
    scene.camera.near = 0.1;
    scene.camera.far = 100;
    scene.polygons.push_back({1, algo::okabe_ito::as<algo::Color>(algo::okabe_ito::sky_blue), {glm::dvec4(t.a, 1), glm::dvec4(t.b, 1), glm::dvec4(t.c, 1)}});
    return scene;
}

struct Tested {
    algo::FaceTested event;
    std::string sentence;
    std::size_t step;
};

// The triangle's test event in the machine the window plays on the scene: its only FaceTested.
std::optional<Tested> run(const algo::Scene& scene, algo::BackfaceTest test) {
    auto machine = algo::cull_back_faces(algo::faces_of(scene), scene.camera, test);
    std::size_t step = 0;
    for (const algo::CullEvent* e = machine.next(); e; e = machine.next(), ++step)
        if (const auto* f = std::get_if<algo::FaceTested>(e)) return Tested{*f, algo::describe(*e), step};
    return std::nullopt;
}
// What the questions say, each template once (the catalogues' [exercise.backface] translate them).
namespace say {
using algo::Saying;
constexpr Saying facing_view_vector{"backface.facing_view_vector",
                                    "Back-face culling by the view-vector test: the eye is at {eye}; the triangle {triangle} is "
                                    "wound counter-clockwise seen from its front. Is it front-facing or back-facing?"};
constexpr Saying facing_plane_equation{"backface.facing_plane_equation",
                                       "Back-face culling by the plane-equation test: the eye is at {eye}; the triangle {triangle} "
                                       "is wound counter-clockwise seen from its front. Is it front-facing or back-facing?"};
constexpr Saying front{"backface.front", "front-facing: kept"};
constexpr Saying back{"backface.back", "back-facing: culled"};
constexpr Saying distance{"backface.distance",
                          "Back-face culling by the plane equation: the triangle {triangle} is wound counter-clockwise seen "
                          "from its front, and N = (B − A) × (C − A) scaled to unit length, D = −N · A. The eye is at {eye}. "
                          "What is N · eye + D (its signed distance from the plane)? Two decimals are enough."};
constexpr Saying all[] = {facing_view_vector, facing_plane_equation, front, back, distance};
}  // namespace say

std::string algorithm_id(algo::BackfaceTest test) {
    return test == algo::BackfaceTest::view_vector ? "backface_view_vector" : "backface_plane_equation";
}

std::string triangle_text(const Drawn& t) {
    return "A = " + point_text(t.a) + ", B = " + point_text(t.b) + ", C = " + point_text(t.c);
}
nlohmann::json given(const Drawn& t, const char* kind) {
    return {{"kind", kind}, {"a", numbers(t.a)}, {"b", numbers(t.b)}, {"c", numbers(t.c)}, {"eye", numbers(t.eye)}};
}


std::optional<Exercise> facing_exercise(Dice& d, Level l) {
    const auto t = draw(d, l);
    if (!t) return std::nullopt;
    const algo::BackfaceTest test = d.coin() ? algo::BackfaceTest::view_vector : algo::BackfaceTest::plane_equation;
    algo::Scene scene = scene_of(*t);
    const auto tested = run(scene, test);
    if (!tested || tested->event.facing == algo::Facing::edge_on) return std::nullopt;
    Exercise x;
    x.ask(Wording(test == algo::BackfaceTest::view_vector ? say::facing_view_vector : say::facing_plane_equation,
                  {{"eye", point_text(t->eye)}, {"triangle", triangle_text(*t)}}));
    x.offer({Wording(say::front), Wording(say::back)}, tested->event.facing == algo::Facing::front ? 0 : 1);
    x.deciding = tested->sentence;
    x.deciding_step = tested->step;
    x.given = given(*t, "facing");
    x.scene = std::move(scene);
    x.algorithm = algorithm_id(test);
    return x;
}

std::optional<Exercise> distance_exercise(Dice& d, Level l) {
    const auto t = draw(d, l);
    if (!t) return std::nullopt;
    algo::Scene scene = scene_of(*t);
    const auto tested = run(scene, algo::BackfaceTest::plane_equation);
    if (!tested) return std::nullopt;
    Exercise x;
    x.ask(Wording(say::distance, {{"eye", point_text(t->eye)}, {"triangle", triangle_text(*t)}}));
    x.answer = decimal_text(tested->event.value, 4);
    x.tolerance = 0.005;
    x.deciding = tested->sentence;
    x.deciding_step = tested->step;
    x.given = given(*t, "distance");
    x.scene = std::move(scene);
    x.algorithm = algorithm_id(algo::BackfaceTest::plane_equation);
    return x;
}

}  // namespace

std::vector<Topic> backface_topics() {
    return {{"backface", "Back-face culling: facing and the plane equation",
             {"backface_view_vector", "backface_plane_equation", "backface_screen_winding"}, [](Draw draw) {
                 Dice d(draw.seed);
                 return d.coin() ? facing_exercise(d, draw.level) : distance_exercise(d, draw.level);
             },
             {say::all}}};
}

}  // namespace hsr::viz::practice
