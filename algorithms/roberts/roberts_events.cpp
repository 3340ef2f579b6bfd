// SPDX-License-Identifier: MIT
#include "roberts/roberts_events.h"

#include "core/events.h"
#include "core/overloaded.h"

namespace hsr::algo {

namespace {
// What Roberts' machine says, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying found{"roberts.found", "{bodies} convex bodies with {edges} edges: each edge is compared with every other body."};
constexpr Saying removed{"roberts.removed", "Edge {edge} of body {body}: both its faces face away from the eye. Removed."};
constexpr Saying hides{"roberts.hides", "Edge {edge} against body {by}: it hides the part from t = {t0} to {t1}."};
constexpr Saying clear{"roberts.clear", "Edge {edge} against body {by}: no part hidden."};
constexpr Saying finished{"roberts.finished", "Edge {edge}: {hidden}% of it hidden, {pieces} visible {pieces?piece|pieces} to draw."};
constexpr Saying done{"roberts.done", "Done: {drawn} edges drawn, {removed} removed as back edges, {tests} edge-against-body tests."};
constexpr Saying bound{"roberts.bound", "Stopped: the step bound of {tests} edge-against-body tests was reached."};
constexpr Saying all[] = {found, removed, hides, clear, finished, done, bound};
}  // namespace say
}  // namespace

std::span<const Saying> roberts_sayings() { return say::all; }

Phrase phrase(const RobertsEvent& event) {
    const auto n = [](auto v) { return std::to_string(v); };
    return std::visit(
        overloaded{
            [&](const BodiesFound& e) { return Phrase(say::found, {{"bodies", n(e.bodies)}, {"edges", n(e.edges)}}); },
            [&](const EdgeRemoved& e) { return Phrase(say::removed, {{"edge", n(e.edge)}, {"body", n(e.body)}}); },
            [&](const EdgeTested& e) {
                if (!e.hides) return Phrase(say::clear, {{"edge", n(e.edge)}, {"by", n(e.by)}});
                return Phrase(say::hides, {{"edge", n(e.edge)}, {"by", n(e.by)}, {"t0", format_number(e.t0)}, {"t1", format_number(e.t1)}});
            },
            [&](const EdgeFinished& e) {
                return Phrase(say::finished, {{"edge", n(e.edge)}, {"hidden", format_number(100 * e.hidden)}, {"pieces", n(e.pieces)}});
            },
            [&](const RobertsFinished& e) {
                if (e.bounded) return Phrase(say::bound, {{"tests", n(e.tests)}});
                return Phrase(say::done, {{"drawn", n(e.drawn)}, {"removed", n(e.removed)}, {"tests", n(e.tests)}});
            },
        },
        event);
}

std::string describe(const RobertsEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
