// SPDX-License-Identifier: MIT
// Practice for the floating horizon: a small terrain of whole-numbered heights, a screen of a few columns, and one
// point of one curve to place against the horizons: above the upper, below the lower, or hidden. The answer is the
// PointTested event of the lesson's own machine on the exercise's terrain.
#include <cmath>
#include <string>

#include "horizon/floating_horizon.h"
#include "state/practice/practice.h"
#include "state/practice/practice_random.h"

namespace hsr::viz::practice {
namespace {

// What the questions say, each template once (the catalogues' [exercise.horizon] translate them).
namespace say {
using algo::Saying;
constexpr Saying sight{"horizon.sight",
                       "The floating horizon draws a terrain seen from {elevation}° above, nearest curve first, on a screen of "
                       "{columns} columns; column c samples x = (c + 0.5) · {width} / {columns}, between samples 1 apart. "
                       "Heights by row (z = 0, 1, …), nearest first: {rows}. Curve {row}, column {column}: is the point above "
                       "the upper horizon, below the lower one, or hidden?"};
constexpr Saying above{"horizon.above", "above"};
constexpr Saying below{"horizon.below", "below"};
constexpr Saying hidden{"horizon.hidden", "hidden"};
constexpr Saying all[] = {sight, above, below, hidden};
}  // namespace say

std::optional<Exercise> sight_exercise(Dice& d, Level level) {
    // Easy: 3 curves of 4 samples; harder: more curves, and heights that fall away (points below the lower horizon)
    const int rows = 2 + int(level), samples = 4;
    const int low = level == Level::easy ? 0 : -3;
    const double elevation = d.pick(std::vector<double>{30.0, 45.0});
    algo::Terrain t{.columns = samples, .rows = rows, .elevation = elevation};
    for (int k = 0; k < samples * rows; ++k) t.heights.push_back(double(low + d.below(4 - low)));
    const int columns = 2 * (samples - 1);  // two columns between each pair of samples
    const int row = 1 + d.below(rows - 1), column = d.below(columns);
    std::vector<algo::HorizonEvent> events;
    auto machine = algo::floating_horizon(t, {.columns = columns});
    while (const algo::HorizonEvent* e = machine.next()) events.push_back(*e);
    std::optional<std::size_t> step, started;
    for (std::size_t k = 0; k < events.size(); ++k) {
        if (const auto* s = std::get_if<algo::CurveStarted>(&events[k]); s && s->row == row) started = k;
        if (const auto* p = std::get_if<algo::PointTested>(&events[k]); p && p->row == row && p->column == column) step = k;
    }
    if (!step || !started) return std::nullopt;
    const auto& tested = std::get<algo::PointTested>(events[*step]);
    // Never on a tie, nor within rounding of one (at 45° rows 2.25 · cos apart in two ways can round apart): a point
    // on a horizon is a rule to learn, not a sum to do
    const auto near = [&](double horizon) { return std::abs(tested.y - horizon) < 1e-9; };
    if (!tested.first && (near(tested.upper) || near(tested.lower))) return std::nullopt;
    std::string heights;
    for (int j = 0; j < rows; ++j) {
        heights += j ? "; [" : "[";
        for (int i = 0; i < samples; ++i) heights += (i ? ", " : "") + number_text(t.height(i, j));
        heights += "]";
    }
    Exercise e;
    e.ask(Wording(say::sight, {{"elevation", number_text(elevation)}, {"columns", std::to_string(columns)}, {"width", number_text(t.width())},
                               {"rows", heights}, {"row", std::to_string(row)}, {"column", std::to_string(column)}}));
    e.offer({Wording(say::above), Wording(say::below), Wording(say::hidden)}, std::size_t(tested.sight));
    e.deciding = algo::describe(events[*step]);
    e.deciding_step = *step;
    e.hold_at = *started;
    e.given = {{"kind", "horizon_sight"}, {"heights", t.heights}, {"samples", samples}, {"rows", rows}, {"elevation", elevation}, {"columns", columns},
               {"row", row}, {"column", column}};
    e.scene.name = "practice terrain";
    e.scene.terrain = std::move(t);
    e.algorithm = "floating_horizon";
    e.columns = columns;
    return e;
}

}  // namespace

std::vector<Topic> horizon_topics() {
    return {{"horizon", "Floating horizon: above, below or hidden", {"floating_horizon"}, [](Draw draw) {
                 Dice d(draw.seed);
                 return sight_exercise(d, draw.level);
             },
             {say::all}}};
}

}  // namespace hsr::viz::practice
