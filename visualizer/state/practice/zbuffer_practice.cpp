// SPDX-License-Identifier: MIT
// Practice for the z-buffer, on fat pixels a student can count: triangles given in pixel coordinates, each at one
// depth (seen head-on by an orthographic camera), drawn in order into a 32 × 24 grid. Does a pixel pass the depth
// test when a triangle is drawn? Which triangle is seen at a pixel at the end? Every answer is an event of the
// z-buffer lesson's own machine (pixel by pixel, 24-bit depths) on the exercise's scene.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "state/practice/pixel_triangles.h"
#include "zbuffer/zbuffer_events.h"
#include "zbuffer/zbuffer_fill.h"

namespace hsr::viz::practice {
namespace {

std::vector<algo::ZBufferEvent> play(const algo::Scene& scene) {
    const algo::ZBufferOptions o = algo::zbuffer_options(scene, pixel_grid, algo::DepthFormat::int24, algo::EventDetail::pixel);
    std::vector<algo::ZBufferEvent> events;
    auto machine = algo::zbuffer_fill(algo::project_polygons(scene, pixel_grid), o);
    while (const algo::ZBufferEvent* e = machine.next()) events.push_back(*e);
    return events;
}

// What the questions say, each template once (the catalogues' [exercise.zbuffer] translate them).
namespace say {
using algo::Saying;
constexpr Saying depth_test{"zbuffer.depth_test",
                            "The z-buffer draws {triangles} When triangle {triangle} is drawn, pixel ({x}, {y}) is tested. "
                            "Does it pass the depth test?"};
constexpr Saying passes{"zbuffer.passes", "it passes: the triangle is nearer, its colour and depth are written"};
constexpr Saying fails{"zbuffer.fails", "it fails: what the buffer holds is nearer"};
constexpr Saying visible{"zbuffer.visible", "The z-buffer draws {triangles} Which triangle is seen at pixel ({x}, {y}) when all are drawn?"};
constexpr Saying all[] = {depth_test, passes, fails, visible};
}  // namespace say

std::optional<Exercise> depth_test_exercise(Dice& d, Level l) {
    const auto t = draw_pixel_triangles(d, l);
    if (!t) return std::nullopt;
    const auto pixel = pick_pixel(d, *t, 2);
    if (!pixel) return std::nullopt;
    const auto [x, y] = *pixel;
    algo::Scene scene = pixel_triangle_scene(*t);
    const std::vector<algo::ZBufferEvent> events = play(scene);
    // the last test at the pixel: by a triangle that found another already there
    std::optional<std::size_t> step_of_test;
    std::uint32_t drawing = 0, polygon = 0;
    for (std::size_t step = 0; step < events.size(); ++step) {
        if (const auto* s = std::get_if<algo::PolygonFillStarted>(&events[step])) drawing = s->index;
        if (const auto* p = std::get_if<algo::PixelTested>(&events[step]); p && p->x == x && p->y == y && drawing > 0)
            step_of_test = step, polygon = drawing;
    }
    if (!step_of_test) return std::nullopt;
    const auto& tested = std::get<algo::PixelTested>(events[*step_of_test]);
    Exercise e;
    e.ask(Wording(say::depth_test, {{"triangle", std::to_string(polygon + 1)}, {"x", std::to_string(x)}, {"y", std::to_string(y)}},
                  {{"triangles", {pixel_triangles_text(*t)}}}));
    e.offer({Wording(say::passes), Wording(say::fails)}, tested.passes ? 0 : 1);
    e.deciding = algo::describe(events[*step_of_test], algo::DepthFormat::int24);
    e.deciding_step = *step_of_test;
    e.given = pixel_triangles_given(*t, "depth_test", x, y, polygon + 1);
    e.scene = std::move(scene);
    e.algorithm = "zbuffer_fill";
    return e;
}

std::optional<Exercise> visible_exercise(Dice& d, Level l) {
    const auto t = draw_pixel_triangles(d, l);
    if (!t) return std::nullopt;
    const auto pixel = pick_pixel(d, *t, 2);
    if (!pixel) return std::nullopt;
    const auto [x, y] = *pixel;
    algo::Scene scene = pixel_triangle_scene(*t);
    const std::vector<algo::ZBufferEvent> events = play(scene);
    // the first comparison at the pixel (a triangle finding another there) is where the answer starts to show
    std::optional<std::size_t> last_write, first_comparison;
    std::uint32_t drawing = 0;
    for (std::size_t step = 0; step < events.size(); ++step) {
        if (const auto* s = std::get_if<algo::PolygonFillStarted>(&events[step])) drawing = s->index;
        if (const auto* p = std::get_if<algo::PixelTested>(&events[step]); p && p->x == x && p->y == y && drawing > 0 && !first_comparison)
            first_comparison = step;
        if (const auto* w = std::get_if<algo::DepthWritten>(&events[step]); w && w->x == x && w->y == y) last_write = step;
    }
    if (!last_write) return std::nullopt;
    Exercise e;
    e.ask(Wording(say::visible, {{"x", std::to_string(x)}, {"y", std::to_string(y)}}, {{"triangles", {pixel_triangles_text(*t)}}}));
    e.offer(triangle_choices(t->size()), std::get<algo::DepthWritten>(events[*last_write]).index);
    e.deciding = algo::describe(events[*last_write], algo::DepthFormat::int24);
    e.deciding_step = *last_write;
    e.hold_at = std::min(first_comparison.value_or(*last_write), *last_write);  // the first triangle may win
    e.given = pixel_triangles_given(*t, "visible", x, y, 0);
    e.scene = std::move(scene);
    e.algorithm = "zbuffer_fill";
    return e;
}

}  // namespace

std::vector<Topic> zbuffer_topics() {
    return {{"zbuffer", "Z-buffer: the depth test, pixel by pixel", {"zbuffer_fill"}, [](Draw draw) {
                 Dice d(draw.seed);
                 return d.coin() ? depth_test_exercise(d, draw.level) : visible_exercise(d, draw.level);
             },
             {say::all, pixel_triangle_sayings()}}};
}

}  // namespace hsr::viz::practice
