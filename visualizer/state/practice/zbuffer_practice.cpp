// SPDX-License-Identifier: MIT
// Practice for the z-buffer, on fat pixels a student can count: triangles given in pixel coordinates, each at one
// depth (seen head-on by an orthographic camera), drawn in order into a 32 × 24 grid. Does a pixel pass the depth
// test when a triangle is drawn? Which triangle is seen at a pixel at the end? Every answer is an event of the
// z-buffer lesson's own machine (pixel by pixel, 24-bit depths) on the exercise's scene.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "raster/screen_polygon.h"
#include "state/practice/practice.h"
#include "state/practice/practice_random.h"
#include "zbuffer/zbuffer_events.h"
#include "zbuffer/zbuffer_fill.h"

namespace hsr::viz::practice {
namespace {

using glm::dvec2;

constexpr algo::Viewport grid{32, 24};  // a lesson's grid when it names none
constexpr double eye_z = 10;            // the camera's; a triangle at world z is at distance 10 − z

struct Triangle {
    dvec2 corner[3];  // pixel coordinates: x right, y down, pixel (i, j) is the square [i, i+1) × [j, j+1)
    double depth;     // the distance from the eye
};

std::string number_text(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// The signed area of (a, b, p), in pixels²: which side of the edge a → b the point p is on.
double edge(dvec2 a, dvec2 b, dvec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }
bool covers(const Triangle& t, dvec2 p) {
    const double e0 = edge(t.corner[0], t.corner[1], p), e1 = edge(t.corner[1], t.corner[2], p), e2 = edge(t.corner[2], t.corner[0], p);
    return (e0 > 0 && e1 > 0 && e2 > 0) || (e0 < 0 && e1 < 0 && e2 < 0);
}
// A pixel centre a hair from an edge is decided by the fill rule and the rounding, not by the question.
bool near_an_edge(const Triangle& t, dvec2 p) {
    for (int k = 0; k < 3; ++k) {
        const dvec2 a = t.corner[k], b = t.corner[(k + 1) % 3];
        if (std::abs(edge(a, b, p)) / glm::length(b - a) < 0.1) return true;
    }
    return false;
}

// Two (easy) or three triangles with corners on whole pixels, at whole depths 2 … 9 (hard: two of them a
// twentieth apart, nearly level, never equal), none of them thin.
std::optional<std::vector<Triangle>> draw(Dice& d, Level l) {
    const int count = l == Level::easy ? 2 : 3;
    std::vector<double> depths = {2, 3, 4, 5, 6, 7, 8, 9};
    for (std::size_t i = depths.size(); i > 1; --i) std::swap(depths[i - 1], depths[std::size_t(d.below(int(i)))]);
    std::vector<Triangle> t;
    for (int k = 0; k < count; ++k) {
        Triangle tri{};
        for (dvec2& c : tri.corner) c = {d.grid(1, grid.width - 1, 1), d.grid(1, grid.height - 1, 1)};
        if (std::abs(edge(tri.corner[0], tri.corner[1], tri.corner[2])) < 40) return std::nullopt;  // at least 20 px²
        tri.depth = depths[std::size_t(k)];
        t.push_back(tri);
    }
    if (l == Level::hard) t[1].depth = t[0].depth + (d.coin() ? 0.05 : -0.05);
    return t;
}

algo::Scene scene_of(const std::vector<Triangle>& triangles) {
    static const algo::Color colours[] = {{230, 159, 0}, {86, 180, 233}, {0, 158, 115}};
    algo::Scene scene;
    scene.name = "triangles on fat pixels";
    scene.camera.projection = algo::Projection::orthographic;
    scene.camera.eye = {0, 0, eye_z};
    scene.camera.target = {0, 0, 0};
    scene.camera.near = 1;
    scene.camera.far = eye_z;
    // eye space x = pixel x, eye space y = −pixel y: the box is the grid
    scene.camera.box[0] = 0, scene.camera.box[1] = grid.width, scene.camera.box[2] = -grid.height, scene.camera.box[3] = 0;
    for (std::size_t k = 0; k < triangles.size(); ++k) {
        algo::ScenePolygon p{algo::SceneId(k + 1), colours[k % 3], {}};
        for (const dvec2& c : triangles[k].corner) p.vertices.emplace_back(c.x, -c.y, eye_z - triangles[k].depth, 1);
        scene.polygons.push_back(p);
    }
    return scene;
}

std::vector<algo::ZBufferEvent> play(const algo::Scene& scene) {
    const algo::ZBufferOptions o = algo::zbuffer_options(scene, grid, algo::DepthFormat::int24, algo::EventDetail::pixel);
    std::vector<algo::ZBufferEvent> events;
    auto machine = algo::zbuffer_fill(algo::project_polygons(scene, grid), o);
    while (const algo::ZBufferEvent* e = machine.next()) events.push_back(*e);
    return events;
}

std::string setting(const std::vector<Triangle>& t) {
    std::string s = "The z-buffer draws ";
    for (std::size_t k = 0; k < t.size(); ++k) {
        s += (k == 0 ? "" : k + 1 == t.size() ? " and then " : ", then ") + std::string("triangle ") + std::to_string(k + 1) + " (";
        for (int c = 0; c < 3; ++c) s += (c ? ", " : "") + std::string("(") + number_text(t[k].corner[c].x) + ", " + number_text(t[k].corner[c].y) + ")";
        s += ", depth " + number_text(t[k].depth) + ")";
    }
    return s + " into a 32 × 24 grid: corners in pixels, x to the right and y down, pixel (i, j) the square from (i, j) to "
               "(i + 1, j + 1) tested at its centre; depth is the distance from the eye, and the nearer wins.";
}

nlohmann::json given(const std::vector<Triangle>& t, const char* kind, int x, int y, std::size_t drawn) {
    nlohmann::json tri = nlohmann::json::array();
    for (const Triangle& k : t)
        tri.push_back({{"corners", {{k.corner[0].x, k.corner[0].y}, {k.corner[1].x, k.corner[1].y}, {k.corner[2].x, k.corner[2].y}}},
                       {"depth", k.depth}});
    return {{"kind", kind}, {"triangles", tri}, {"pixel", {x, y}}, {"triangle", drawn}};
}

// Pixels whose centre lies inside at least two triangles, and a hair from no edge: where the depth test decides.
std::vector<std::pair<int, int>> overlaps(const std::vector<Triangle>& t) {
    std::vector<std::pair<int, int>> at;
    for (int y = 0; y < grid.height; ++y)
        for (int x = 0; x < grid.width; ++x) {
            const dvec2 centre(x + 0.5, y + 0.5);
            int inside = 0;
            bool clear = true;
            for (const Triangle& k : t) {
                inside += covers(k, centre);
                clear = clear && !near_an_edge(k, centre);
            }
            if (inside >= 2 && clear) at.emplace_back(x, y);
        }
    return at;
}

const std::vector<std::string> test_choices = {"it passes: the triangle is nearer, its colour and depth are written",
                                               "it fails: what the buffer holds is nearer"};

std::optional<Exercise> depth_test_exercise(Dice& d, Level l) {
    const auto t = draw(d, l);
    if (!t) return std::nullopt;
    const auto pixels = overlaps(*t);
    if (pixels.empty()) return std::nullopt;
    const auto [x, y] = pixels[std::size_t(d.below(int(pixels.size())))];
    algo::Scene scene = scene_of(*t);
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
    e.question = setting(*t) + " When triangle " + std::to_string(polygon + 1) + " is drawn, pixel (" + std::to_string(x) + ", " +
                 std::to_string(y) + ") is tested. Does it pass the depth test?";
    e.choices = test_choices;
    e.answer = test_choices[tested.passes ? 0 : 1];
    e.deciding = algo::describe(events[*step_of_test], algo::DepthFormat::int24);
    e.deciding_step = *step_of_test;
    e.given = given(*t, "depth_test", x, y, polygon + 1);
    e.scene = std::move(scene);
    e.algorithm = "zbuffer_fill";
    return e;
}

std::optional<Exercise> visible_exercise(Dice& d, Level l) {
    const auto t = draw(d, l);
    if (!t) return std::nullopt;
    const auto pixels = overlaps(*t);
    if (pixels.empty()) return std::nullopt;
    const auto [x, y] = pixels[std::size_t(d.below(int(pixels.size())))];
    algo::Scene scene = scene_of(*t);
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
    e.question = setting(*t) + " Which triangle is seen at pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                 ") when all are drawn?";
    for (std::size_t k = 0; k < t->size(); ++k) e.choices.push_back("triangle " + std::to_string(k + 1));
    e.choices.push_back("none: the background");
    e.answer = e.choices[std::get<algo::DepthWritten>(events[*last_write]).index];
    e.deciding = algo::describe(events[*last_write], algo::DepthFormat::int24);
    e.deciding_step = *last_write;
    e.hold_at = std::min(first_comparison.value_or(*last_write), *last_write);  // the first triangle may win
    e.given = given(*t, "visible", x, y, 0);
    e.scene = std::move(scene);
    e.algorithm = "zbuffer_fill";
    return e;
}

}  // namespace

std::vector<Topic> zbuffer_topics() {
    return {{"zbuffer", "Z-buffer: the depth test, pixel by pixel", {"zbuffer_fill"}, [](Draw draw) {
                 Dice d(draw.seed);
                 return d.coin() ? depth_test_exercise(d, draw.level) : visible_exercise(d, draw.level);
             }}};
}

}  // namespace hsr::viz::practice
