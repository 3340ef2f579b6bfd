// SPDX-License-Identifier: MIT
// Practice for ray casting, on the z-buffer's fat pixels: one ray through a pixel's centre, tested against every
// triangle (the brute-force cast of the notes, O(pP)). How many triangles does it hit? Which one does it see? Every
// answer is an event of the ray-casting lesson's own machine on the exercise's scene.
#include "raycast/ray_cast.h"
#include "raycast/raycast_events.h"
#include "state/practice/pixel_triangles.h"

namespace hsr::viz::practice {
namespace {

std::vector<algo::RayCastEvent> play(const algo::Scene& scene) {
    std::vector<algo::RayCastEvent> events;
    auto machine = algo::ray_cast(scene, {.viewport = pixel_grid, .acceleration = algo::Acceleration::none, .detail = algo::RayDetail::test});
    while (const algo::RayCastEvent* e = machine.next()) events.push_back(*e);
    return events;
}

struct RayAt {
    std::size_t started = 0, finished = 0;  // the steps of RayStarted and RayFinished of the pixel
    int hits = 0;
};

std::optional<RayAt> ray_at(const std::vector<algo::RayCastEvent>& events, int x, int y) {
    std::optional<RayAt> ray;
    for (std::size_t step = 0; step < events.size(); ++step) {
        if (const auto* s = std::get_if<algo::RayStarted>(&events[step]); s && s->x == x && s->y == y) ray = RayAt{step, 0, 0};
        if (!ray || ray->finished) continue;
        if (const auto* t = std::get_if<algo::PrimitiveTested>(&events[step]); t && t->hit) ++ray->hits;
        if (std::holds_alternative<algo::RayFinished>(events[step])) ray->finished = step;
    }
    return ray && ray->finished ? ray : std::nullopt;
}

// Triangles, a pixel, and the cast of the scene with that pixel's ray found in it.
struct Cast {
    std::vector<PixelTriangle> triangles;
    int x, y;
    algo::Scene scene;
    std::vector<algo::RayCastEvent> events;
    RayAt ray;
};

// A pixel covered by at least one triangle (one time in three by none: a ray that hits nothing is a fair question).
std::optional<Cast> cast(Dice& d, Level l) {
    auto t = draw_pixel_triangles(d, l);
    if (!t) return std::nullopt;
    const auto pixel = pick_pixel(d, *t, d.below(3) == 0 ? 0 : 1);
    if (!pixel) return std::nullopt;
    const auto [x, y] = *pixel;
    algo::Scene scene = pixel_triangle_scene(*t);
    std::vector<algo::RayCastEvent> events = play(scene);
    const auto ray = ray_at(events, x, y);
    if (!ray) return std::nullopt;
    return Cast{std::move(*t), x, y, std::move(scene), std::move(events), *ray};
}

// What the questions say, each template once (the catalogues' [exercise.raycast] translate them).
namespace say {
using algo::Saying;
constexpr Saying hits{"raycast.hits",
                      "Ray casting, every triangle tested: {triangles} How many of the triangles does the ray through pixel "
                      "({x}, {y}) hit?"};
constexpr Saying nearest{"raycast.nearest", "Ray casting, every triangle tested: {triangles} Which triangle does the ray through pixel ({x}, {y}) see?"};
constexpr Saying all[] = {hits, nearest};
}  // namespace say

// What both questions share: the scene, where the ray starts (the hold) and where it ends (the deciding event).
Exercise exercise_on(Cast& c, const algo::Saying& asked, const char* kind) {
    Exercise e;
    e.ask(Wording(asked, {{"x", std::to_string(c.x)}, {"y", std::to_string(c.y)}}, {{"triangles", {pixel_triangles_text(c.triangles)}}}));
    e.deciding = algo::describe(c.events[c.ray.finished]);
    e.deciding_step = c.ray.finished;
    e.hold_at = c.ray.started;
    e.given = pixel_triangles_given(c.triangles, kind, c.x, c.y, 0);
    e.scene = std::move(c.scene);
    e.algorithm = "raycast_brute";
    return e;
}


std::optional<Exercise> hits_exercise(Dice& d, Level l) {
    auto c = cast(d, l);
    if (!c) return std::nullopt;
    const int hits = c->ray.hits;
    Exercise e = exercise_on(*c, say::hits, "hits");
    e.answer = std::to_string(hits);
    e.tolerance = 0;
    return e;
}

std::optional<Exercise> nearest_exercise(Dice& d, Level l) {
    auto c = cast(d, l);
    if (!c) return std::nullopt;
    const auto index = std::get<algo::RayFinished>(c->events[c->ray.finished]).index;
    const std::size_t triangles = c->triangles.size();
    Exercise e = exercise_on(*c, say::nearest, "visible");
    e.offer(triangle_choices(triangles), index < 0 ? triangles : std::size_t(index));
    return e;
}

}  // namespace

std::vector<Topic> raycast_topics() {
    return {{"raycast", "Ray casting: what a ray hits and sees", {"raycast_brute", "raycast_grid", "raycast_octree"}, [](Draw draw) {
                 Dice d(draw.seed);
                 return d.coin() ? hits_exercise(d, draw.level) : nearest_exercise(d, draw.level);
             },
             {say::all, pixel_triangle_sayings()}}};
}

}  // namespace hsr::viz::practice
