// SPDX-License-Identifier: MIT
// Practice for depth precision: two squares face a perspective camera, the farther drawn first, the nearer a little
// nearer. A 24-bit buffer stores round((2^24 − 1)(a + b/z)) with a = f/(f − n), b = f·n/(n − f) (the notes' form).
// How many codes apart are the two squares? Does the nearer one pass the depth test, or do they share a code and
// fight? Every answer is the PixelTested event of the z-buffer lesson's own machine at the middle pixel.
#include <cmath>
#include <cstdio>

#include "state/practice/pixel_triangles.h"
#include "zbuffer/zbuffer_events.h"
#include "zbuffer/zbuffer_fill.h"
#include "core/okabe_ito.h"

namespace hsr::viz::practice {
namespace {

constexpr algo::DepthFormat format = algo::DepthFormat::int24;

std::string ten_digit_text(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", v);  // 39.999953 must not print as 40
    return text;
}

struct Drawn {
    double near, far, farther, nearer;  // the camera's range and the squares' distances from the eye
};

// Ranges from the lessons: near 1 and far 100 (easy), near 0.1 and far 1000 (medium), near 0.01 and far 1000
// (hard: most codes are spent next to the eye). The squares are 0.2 codes to `most_codes` apart.
std::optional<Drawn> draw(Dice& d, Level l, double most_codes) {
    Drawn s{};
    if (l == Level::easy) s.near = 1, s.far = 100, s.farther = d.grid(20, 90, 10);
    else if (l == Level::medium) s.near = 0.1, s.far = 1000, s.farther = d.grid(100, 900, 50);
    else s.near = 0.01, s.far = 1000, s.farther = d.grid(20, 200, 10);
    const double step = algo::resolvable_step(format, s.farther, {s.near, s.far});
    // a gap of 0.2 codes … most_codes, on a grid of a few digits
    const double gap = step * d.grid(2, most_codes * 10, 1) / 10;
    const double scale = std::pow(10.0, std::floor(std::log10(gap)) - 1);
    s.nearer = s.farther - std::round(gap / scale) * scale;
    if (!(s.nearer > s.near && s.nearer < s.farther)) return std::nullopt;
    // neither code a hair from a half, where the rounding of a rasteriser's interpolated depth could go either way
    for (const double z : {s.farther, s.nearer}) {
        const double code = window_depth_levels(format) * algo::window_depth(z, {s.near, s.far});
        if (std::abs(code - std::floor(code) - 0.5) < 0.02) return std::nullopt;
    }
    return s;
}

algo::Scene scene_of(const Drawn& s) {
    algo::Scene scene;
    scene.name = "two squares far from the eye";
    scene.camera.eye = {0, 0, 0};
    scene.camera.target = {0, 0, -1};
    scene.camera.fov_y = 50;
    scene.camera.near = s.near;
    scene.camera.far = s.far;
    scene.camera.aspect = double(pixel_grid.width) / pixel_grid.height;
    const algo::Color colours[] = {algo::okabe_ito::as<algo::Color>(algo::okabe_ito::orange), algo::okabe_ito::as<algo::Color>(algo::okabe_ito::sky_blue)};
    const double half[] = {0.3, 0.15};  // of the distance: the nearer square is the smaller one on screen
    const double z[] = {s.farther, s.nearer};
    for (std::size_t k = 0; k < 2; ++k) {
        const double r = half[k] * z[k];
        scene.polygons.push_back({algo::SceneId(k + 1), colours[k], {{-r, -r, -z[k], 1}, {r, -r, -z[k], 1}, {r, r, -z[k], 1}, {-r, r, -z[k], 1}}});
    }
    return scene;
}

struct Tested {
    algo::PixelTested event;
    std::size_t step, first_fill;  // the test of the nearer square at the middle pixel; where it starts filling
    std::string sentence;
};

std::optional<Tested> run(const algo::Scene& scene) {
    const algo::ZBufferOptions o = algo::zbuffer_options(scene, pixel_grid, format, algo::EventDetail::pixel);
    auto machine = algo::zbuffer_fill(algo::project_polygons(scene, pixel_grid), o);
    std::uint32_t drawing = 0;
    std::size_t step = 0, fill = 0;
    for (const algo::ZBufferEvent* e = machine.next(); e; e = machine.next(), ++step) {
        if (const auto* s = std::get_if<algo::PolygonFillStarted>(e)) drawing = s->index, fill = step;
        if (const auto* p = std::get_if<algo::PixelTested>(e);
            p && drawing == 1 && p->x == pixel_grid.width / 2 && p->y == pixel_grid.height / 2)
            return Tested{*p, step, fill, algo::describe(*e, format)};
    }
    return std::nullopt;
}

// What the questions say, each template once (the catalogues' [exercise.precision] translate them).
namespace say {
using algo::Saying;
constexpr Saying setting{"precision.setting",
                         "A perspective camera with near = {near} and far = {far} stores depth in 24 bits as "
                         "round((2^24 − 1)(a + b/z)), a = far/(far − near), b = far·near/(near − far). Square 1 at distance "
                         "z = {farther} is drawn first, then square 2 at z = {nearer}, both facing the eye."};
constexpr Saying codes_apart{"precision.codes_apart", "{setting} How many codes apart are the two squares' depths at the middle pixel?"};
constexpr Saying fight{"precision.fight",
                       "{setting} Does square 2 pass the depth test at the middle pixel (the test is strict: nearer means a "
                       "smaller code)?"};
constexpr Saying passes{"precision.passes", "it passes: its code is smaller, square 2 is seen"};
constexpr Saying fails{"precision.fails", "it fails: the two share a code, square 1 stays"};
constexpr Saying all[] = {setting, codes_apart, fight, passes, fails};
}  // namespace say

std::vector<std::pair<std::string_view, std::vector<Wording>>> setting_of(const Drawn& s) {
    return {{"setting",
             {Wording(say::setting, {{"near", ten_digit_text(s.near)},
                                     {"far", ten_digit_text(s.far)},
                                     {"farther", ten_digit_text(s.farther)},
                                     {"nearer", ten_digit_text(s.nearer)}})}}};
}
nlohmann::json given(const Drawn& s, const char* kind) {
    return {{"kind", kind}, {"near", s.near}, {"far", s.far}, {"bits", 24}, {"farther", s.farther}, {"nearer", s.nearer}};
}


std::optional<Exercise> exercise_of(Dice& d, Level l, bool codes_apart) {
    // whether two squares under a code apart share one is the question: most of the fight's gaps are under one
    const auto s = draw(d, l, codes_apart ? 3 : 1.2);
    if (!s) return std::nullopt;
    algo::Scene scene = scene_of(*s);
    const auto tested = run(scene);
    if (!tested) return std::nullopt;
    Exercise e;
    if (codes_apart) {
        e.ask(Wording(say::codes_apart, {}, setting_of(*s)));
        e.answer = std::to_string(tested->event.stored - tested->event.incoming);
        e.tolerance = 0;
    } else {
        e.ask(Wording(say::fight, {}, setting_of(*s)));
        e.offer({Wording(say::passes), Wording(say::fails)}, tested->event.passes ? 0 : 1);
    }
    e.deciding = tested->sentence;
    e.deciding_step = tested->step;
    e.hold_at = tested->first_fill;
    e.given = given(*s, codes_apart ? "codes_apart" : "fight");
    e.scene = std::move(scene);
    e.algorithm = "zbuffer_fill";
    return e;
}

}  // namespace

std::vector<Topic> precision_topics() {
    return {{"precision", "Depth precision: the codes of a 24-bit buffer", {"zbuffer_fill"}, [](Draw draw) {
                 Dice d(draw.seed);
                 return exercise_of(d, draw.level, d.coin());
             },
             {say::all}}};
}

}  // namespace hsr::viz::practice
