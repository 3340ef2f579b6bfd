// SPDX-License-Identifier: MIT
#include "state/horizon_session.h"

#include <cmath>
#include <limits>

#include "core/numeric.h"
#include "core/overloaded.h"
#include "scene/load_terrain.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

const Pseudocode<HorizonEvent> horizon_lines = {
    {"Upper[x] = −∞;  Lower[x] = +∞   (every column x)", {}},
    {"for each curve, nearest first", {micro<CurveStarted>(), step<HorizonFinished>()}},
    {"  for each screen column x", {}},
    {"    y = the curve's height at x, projected", {}},
    {"    if y > Upper[x]: visible, above the horizon", {micro<PointTested>([](const PointTested& e) { return e.sight == Sight::above; })}},
    {"    else if y < Lower[x]: visible, below it", {micro<PointTested>([](const PointTested& e) { return e.sight == Sight::below; })}},
    {"    else: hidden by a nearer curve", {micro<PointTested>()}},
    {"    Upper[x] = max(Upper[x], y);  Lower[x] = min(Lower[x], y)", {}},
    {"  draw the curve where it was visible", {step<CurveDrawn>()}},
    {"/* y equal to a horizon: hidden (it grazes a nearer curve) */", {}},
};

}  // namespace

HorizonView horizon_initial_view(const Lesson& lesson) {
    HorizonView v;
    v.terrain = std::make_shared<const Terrain>(lesson.scene.terrain);
    v.columns = lesson.grid.width;
    const std::size_t points = std::size_t(v.columns) * std::size_t(std::max(0, v.terrain->rows));
    v.y.assign(points, 0.0);
    v.sight.assign(points, Sight::hidden);
    v.tested.assign(points, 0);
    v.upper.assign(std::size_t(v.columns), -std::numeric_limits<double>::infinity());
    v.lower.assign(std::size_t(v.columns), std::numeric_limits<double>::infinity());
    // The screen's range: every sample's screen y (the curves between samples lie between theirs)
    const Terrain& t = *v.terrain;
    const HorizonProjection view(t.elevation);
    for (int j = 0; j < t.rows; ++j)
        for (int i = 0; i < t.columns; ++i) {
            const double y = view.screen_y(t.height(i, j), j * t.dz);
            if (i == 0 && j == 0) v.y_min = v.y_max = y;
            v.y_min = std::min(v.y_min, y), v.y_max = std::max(v.y_max, y);
        }
    if (!(v.y_max > v.y_min)) v.y_min -= 1, v.y_max += 1;  // a flat terrain seen level: one line
    return v;
}

HorizonSession::RunType HorizonSession::machine(const Lesson& lesson) {
    if (lesson.scene.terrain.rows == 0)
        throw InvalidInput(lesson.source + ": the floating horizon needs a scene with a [terrain] (heights, or generate = \"hills\")");
    return {floating_horizon(lesson.scene.terrain, {.columns = lesson.grid.width}), horizon_initial_view(lesson)};
}

void reduce(HorizonView& v, const HorizonEvent& event) {
    std::visit(overloaded{
                   [&](const CurveStarted& e) { v.row = e.row, v.column = -1, v.last.reset(); },
                   [&](const PointTested& e) {
                       const std::size_t k = v.at(e.row, e.column);
                       v.y[k] = e.y, v.sight[k] = e.sight, v.tested[k] = 1;
                       double& up = v.upper[std::size_t(e.column)];
                       double& low = v.lower[std::size_t(e.column)];
                       up = std::max(up, e.y), low = std::min(low, e.y);
                       v.row = e.row, v.column = e.column, v.last = e;
                       ++(e.sight == Sight::hidden ? v.hidden : v.visible);
                   },
                   [&](const CurveDrawn& e) { v.curves_drawn = e.row + 1, v.column = -1, v.last.reset(); },
                   [&](const HorizonFinished&) { v.done = true, v.row = -1; },
               },
               event);
}

std::size_t approx_bytes(const HorizonView& v) {
    return sizeof(HorizonView) + v.y.capacity() * sizeof(double) + v.sight.capacity() + v.tested.capacity() +
           (v.upper.capacity() + v.lower.capacity()) * sizeof(double);
}

HorizonSession::HorizonSession(Lesson lesson, PlayerOptions options) : PlayerSession(lesson, machine(lesson), options) {}

std::string HorizonSession::sentence_of(const HorizonEvent& e, const HorizonView&) { return describe(e); }
std::string HorizonSession::describe_event(const HorizonEvent& e) const { return sentence_of(e, view()); }
std::string HorizonSession::speak_event(const HorizonEvent& e) const { return window_strings().say(phrase(e)); }

const Pseudocode<HorizonEvent>& HorizonSession::table() const { return horizon_lines; }

const FamilyFacts HorizonSession::facts = {
    .topic = "Terrain",
    .speaks_to = [](const algo::Scene& s, const algo::AlgorithmInfo&) { return s.terrain.rows > 0; },
    .random_scene = [](std::uint32_t seed, bool) -> std::optional<algo::Scene> {
        algo::Scene s;
        s.name = "random hills " + std::to_string(seed);
        s.terrain = hills_terrain(20, 12, seed, 25);
        return s;
    },
    .measure = &analysis::measure_horizon,
};

}  // namespace hsr::viz
