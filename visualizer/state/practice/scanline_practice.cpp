// SPDX-License-Identifier: MIT
// Practice for the scan-line algorithm, on the fat-pixel triangles of the z-buffer's practice: how many edges are
// active on a line, where the line goes into a triangle (the edge whose crossing sets its in/out flag), and which
// triangle colours a pixel once the line's z-buffer has settled the spans. Every answer is an event of the scan-line
// lesson's own machine (the active edge table walked left to right) on the exercise's scene.
#include <cmath>

#include "state/practice/pixel_triangles.h"
#include "zbuffer/scanline.h"

namespace hsr::viz::practice {
namespace {

std::vector<algo::ScanLineEvent> play(const algo::Scene& scene) {
    std::vector<algo::ScanLineEvent> events;
    auto machine = algo::scan_line(algo::project_polygons(scene, pixel_grid), algo::scan_line_options(scene, pixel_grid, algo::DepthFormat::int24));
    while (const algo::ScanLineEvent* e = machine.next()) events.push_back(*e);
    return events;
}

// A line that crosses at least one triangle (its centre y + 0.5 strictly inside a triangle's rows).
std::optional<int> pick_line(Dice& d, const std::vector<PixelTriangle>& t) {
    std::vector<int> lines;
    for (int y = 0; y < pixel_grid.height; ++y)
        for (const PixelTriangle& k : t) {
            const double lo = std::min({k.corner[0].y, k.corner[1].y, k.corner[2].y}), hi = std::max({k.corner[0].y, k.corner[1].y, k.corner[2].y});
            if (lo < y + 0.5 && y + 0.5 < hi) {
                lines.push_back(y);
                break;
            }
        }
    if (lines.empty()) return std::nullopt;
    return lines[std::size_t(d.below(int(lines.size())))];
}

// What the questions say, each template once (the catalogues' [exercise.scanline] translate them).
namespace say {
using algo::Saying;
constexpr Saying active_edges{"scanline.active_edges",
                              "The scan-line algorithm draws {triangles} How many edges are in the active edge table on scan "
                              "line {y} (through the pixel centres at y = {y}.5)?"};
constexpr Saying enter_x{"scanline.enter_x",
                         "The scan-line algorithm draws {triangles} On scan line {y} (through the pixel centres at y = {y}.5), "
                         "at what x does the line go into triangle {triangle} (its in/out flag turns in)? Two decimals are enough."};
constexpr Saying span_owner{"scanline.span_owner",
                            "The scan-line algorithm draws {triangles} When scan line {y} (through the pixel centres at y = "
                            "{y}.5) is output as spans, which triangle colours pixel ({x}, {y})?"};
constexpr Saying all[] = {active_edges, enter_x, span_owner};
}  // namespace say

std::optional<Exercise> active_edges_exercise(Dice& d, Level l) {
    const auto t = draw_pixel_triangles(d, l);
    if (!t) return std::nullopt;
    const auto y = pick_line(d, *t);
    if (!y) return std::nullopt;
    algo::Scene scene = pixel_triangle_scene(*t);
    const auto events = play(scene);
    std::optional<std::size_t> started, last_crossing;
    int crossings = 0;
    for (std::size_t step = 0; step < events.size(); ++step) {
        if (const auto* s = std::get_if<algo::ScanLineStarted>(&events[step]); s && s->y == *y) started = step;
        if (const auto* c = std::get_if<algo::EdgeCrossed>(&events[step]); c && c->y == *y) ++crossings, last_crossing = step;
    }
    if (!started || !last_crossing) return std::nullopt;
    Exercise e;
    e.ask(Wording(say::active_edges, {{"y", std::to_string(*y)}}, {{"triangles", {pixel_triangles_text(*t)}}}));
    e.answer = std::to_string(crossings);
    e.tolerance = 0;
    e.deciding = algo::describe(events[*last_crossing]);
    e.deciding_step = *last_crossing;
    e.hold_at = *started;  // before the edges enter and leave the table
    e.given = pixel_triangles_given(*t, "active_edges", 0, *y, 0);
    e.scene = std::move(scene);
    e.algorithm = "scan_line";
    return e;
}

std::optional<Exercise> enter_x_exercise(Dice& d, Level l) {
    const auto t = draw_pixel_triangles(d, l);
    if (!t) return std::nullopt;
    const auto y = pick_line(d, *t);
    if (!y) return std::nullopt;
    algo::Scene scene = pixel_triangle_scene(*t);
    const auto events = play(scene);
    std::vector<std::size_t> entering;  // the steps where a triangle's flag goes in on the line
    std::optional<std::size_t> started;
    for (std::size_t step = 0; step < events.size(); ++step) {
        if (const auto* s = std::get_if<algo::ScanLineStarted>(&events[step]); s && s->y == *y) started = step;
        if (const auto* c = std::get_if<algo::EdgeCrossed>(&events[step]); c && c->y == *y && c->entering) entering.push_back(step);
    }
    if (!started || entering.empty()) return std::nullopt;
    const std::size_t step = entering[std::size_t(d.below(int(entering.size())))];
    const auto& crossed = std::get<algo::EdgeCrossed>(events[step]);
    Exercise e;
    e.ask(Wording(say::enter_x, {{"y", std::to_string(*y)}, {"triangle", std::to_string(crossed.polygon + 1)}},
                  {{"triangles", {pixel_triangles_text(*t)}}}));
    e.answer = decimal_text(crossed.x, 4);
    e.tolerance = 0.005;
    e.deciding = algo::describe(events[step]);
    e.deciding_step = step;
    e.hold_at = *started;
    e.given = pixel_triangles_given(*t, "enter_x", 0, *y, crossed.polygon + 1);
    e.scene = std::move(scene);
    e.algorithm = "scan_line";
    return e;
}

std::optional<Exercise> span_owner_exercise(Dice& d, Level l) {
    const auto t = draw_pixel_triangles(d, l);
    if (!t) return std::nullopt;
    const auto pixel = pick_pixel(d, *t, 1);
    if (!pixel) return std::nullopt;
    const auto [x, y] = *pixel;
    algo::Scene scene = pixel_triangle_scene(*t);
    const auto events = play(scene);
    std::optional<std::size_t> started, span;
    for (std::size_t step = 0; step < events.size() && !span; ++step) {
        if (const auto* s = std::get_if<algo::ScanLineStarted>(&events[step]); s && s->y == y) started = step;
        if (const auto* s = std::get_if<algo::SpanColored>(&events[step]); s && s->y == y && s->x_begin <= x && x < s->x_end) span = step;
    }
    if (!started || !span) return std::nullopt;
    const auto owner = std::get<algo::SpanColored>(events[*span]).polygon;
    Exercise e;
    e.ask(Wording(say::span_owner, {{"x", std::to_string(x)}, {"y", std::to_string(y)}}, {{"triangles", {pixel_triangles_text(*t)}}}));
    e.offer(triangle_choices(t->size()), owner < 0 ? t->size() : std::size_t(owner));
    e.deciding = algo::describe(events[*span]);
    e.deciding_step = *span;
    e.hold_at = *started;
    e.given = pixel_triangles_given(*t, "visible", x, y, 0);
    e.scene = std::move(scene);
    e.algorithm = "scan_line";
    return e;
}

}  // namespace

std::vector<Topic> scanline_topics() {
    return {{"scanline", "Scan line: active edges, in/out flags and spans", {"scan_line"}, [](Draw draw) {
                 Dice d(draw.seed);
                 switch (d.below(3)) {
                     case 0: return active_edges_exercise(d, draw.level);
                     case 1: return enter_x_exercise(d, draw.level);
                     default: return span_owner_exercise(d, draw.level);
                 }
             },
             {say::all, pixel_triangle_sayings()}}};
}

}  // namespace hsr::viz::practice
