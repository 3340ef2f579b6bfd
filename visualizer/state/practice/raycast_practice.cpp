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

// A pixel covered by at least one triangle (one time in three by none: a ray that hits nothing is a fair question).
std::optional<std::tuple<std::vector<PixelTriangle>, int, int>> draw(Dice& d, Level l) {
    const auto t = draw_pixel_triangles(d, l);
    if (!t) return std::nullopt;
    const auto pixels = pixels_covered(*t, d.below(3) == 0 ? 0 : 1);
    if (pixels.empty()) return std::nullopt;
    const auto [x, y] = pixels[std::size_t(d.below(int(pixels.size())))];
    return std::tuple{*t, x, y};
}

std::optional<Exercise> hits_exercise(Dice& d, Level l) {
    const auto drawn = draw(d, l);
    if (!drawn) return std::nullopt;
    const auto& [t, x, y] = *drawn;
    algo::Scene scene = pixel_triangle_scene(t);
    const std::vector<algo::RayCastEvent> events = play(scene);
    const auto ray = ray_at(events, x, y);
    if (!ray) return std::nullopt;
    Exercise e;
    e.question = "Ray casting, every triangle tested: " + pixel_triangles_text(t) + " How many of the triangles does the ray through pixel (" +
                 std::to_string(x) + ", " + std::to_string(y) + ") hit?";
    e.answer = std::to_string(ray->hits);
    e.tolerance = 0;
    e.deciding = algo::describe(events[ray->finished]);
    e.deciding_step = ray->finished;
    e.hold_at = ray->started;
    e.given = pixel_triangles_given(t, "hits", x, y, 0);
    e.scene = std::move(scene);
    e.algorithm = "raycast_brute";
    return e;
}

std::optional<Exercise> nearest_exercise(Dice& d, Level l) {
    const auto drawn = draw(d, l);
    if (!drawn) return std::nullopt;
    const auto& [t, x, y] = *drawn;
    algo::Scene scene = pixel_triangle_scene(t);
    const std::vector<algo::RayCastEvent> events = play(scene);
    const auto ray = ray_at(events, x, y);
    if (!ray) return std::nullopt;
    const auto& finished = std::get<algo::RayFinished>(events[ray->finished]);
    Exercise e;
    e.question = "Ray casting, every triangle tested: " + pixel_triangles_text(t) + " Which triangle does the ray through pixel (" +
                 std::to_string(x) + ", " + std::to_string(y) + ") see?";
    for (std::size_t k = 0; k < t.size(); ++k) e.choices.push_back("triangle " + std::to_string(k + 1));
    e.choices.push_back("none: the background");
    e.answer = finished.index < 0 ? e.choices.back() : e.choices[std::size_t(finished.index)];
    e.deciding = algo::describe(events[ray->finished]);
    e.deciding_step = ray->finished;
    e.hold_at = ray->started;
    e.given = pixel_triangles_given(t, "visible", x, y, 0);
    e.scene = std::move(scene);
    e.algorithm = "raycast_brute";
    return e;
}

}  // namespace

std::vector<Topic> raycast_topics() {
    return {{"raycast", "Ray casting: what a ray hits and sees", {"raycast_brute", "raycast_grid", "raycast_octree"}, [](Draw draw) {
                 Dice d(draw.seed);
                 return d.coin() ? hits_exercise(d, draw.level) : nearest_exercise(d, draw.level);
             }}};
}

}  // namespace hsr::viz::practice
