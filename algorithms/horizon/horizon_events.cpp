// SPDX-License-Identifier: MIT
#include "horizon/horizon_events.h"

#include "core/events.h"
#include "core/overloaded.h"

namespace hsr::algo {

namespace {
// What the floating horizon says (its key is what another language's catalogue translates).
namespace say {
constexpr Saying started{"horizon.started", "Curve {row} (z = {z}): the next nearest; its points are tested against the horizons of the curves in front."};
constexpr Saying first{"horizon.first", "Curve 0, column {column}: y = {y}. The nearest curve is seen everywhere; it starts both horizons at {y}."};
constexpr Saying above{"horizon.above", "Curve {row}, column {column}: y = {y} > upper {upper}, so the point shows above the horizon, which rises to {y}."};
constexpr Saying below{"horizon.below", "Curve {row}, column {column}: y = {y} < lower {lower}, so the point shows below the horizon, which sinks to {y}."};
constexpr Saying hidden{"horizon.hidden", "Curve {row}, column {column}: lower {lower} ≤ y = {y} ≤ upper {upper}, so a nearer curve hides the point."};
constexpr Saying drawn{"horizon.drawn", "Curve {row} drawn where it showed: {above} {above?column|columns} above the horizon, {below} below, {hidden} hidden."};
constexpr Saying finished{"horizon.finished", "Done: {visible} {visible?point|points} drawn, {hidden} hidden, every curve tested once against the horizons."};
constexpr Saying all[] = {started, first, above, below, hidden, drawn, finished};
}  // namespace say
}  // namespace

std::string_view to_string(Sight s) {
    switch (s) {
        case Sight::above: return "above";
        case Sight::below: return "below";
        case Sight::hidden: break;
    }
    return "hidden";
}

std::span<const Saying> horizon_sayings() { return say::all; }

Phrase phrase(const HorizonEvent& event) {
    const auto n = [](auto v) { return std::to_string(v); };
    const auto f = [](double v) { return format_number(v); };
    return std::visit(overloaded{
                          [&](const CurveStarted& e) { return Phrase(say::started, {{"row", n(e.row)}, {"z", f(e.z)}}); },
                          [&](const PointTested& e) {
                              const Saying& s = e.first                    ? say::first
                                                : e.sight == Sight::above  ? say::above
                                                : e.sight == Sight::below  ? say::below
                                                                           : say::hidden;
                              return Phrase(s, {{"row", n(e.row)}, {"column", n(e.column)}, {"y", f(e.y)}, {"upper", f(e.upper)}, {"lower", f(e.lower)}});
                          },
                          [&](const CurveDrawn& e) {
                              return Phrase(say::drawn, {{"row", n(e.row)}, {"above", n(e.above)}, {"below", n(e.below)}, {"hidden", n(e.hidden)}});
                          },
                          [&](const HorizonFinished& e) { return Phrase(say::finished, {{"visible", n(e.visible)}, {"hidden", n(e.hidden)}}); },
                      },
                      event);
}

std::string describe(const HorizonEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
