// SPDX-License-Identifier: MIT
#include "compositing/composite_events.h"

#include <algorithm>
#include <cmath>

#include "core/events.h"
#include "core/overloaded.h"

namespace hsr::algo {

double max_difference(Rgba x, Rgba y) {
    return std::max({std::abs(x.r - y.r), std::abs(x.g - y.g), std::abs(x.b - y.b), std::abs(x.a - y.a)});
}

std::string_view to_string(PorterDuff op) {
    switch (op) {
        case PorterDuff::clear: return "clear";
        case PorterDuff::a: return "A";
        case PorterDuff::b: return "B";
        case PorterDuff::over: return "over";
        case PorterDuff::in: return "in";
        case PorterDuff::out: return "out";
        case PorterDuff::atop: return "atop";
        case PorterDuff::xor_: return "xor";
        case PorterDuff::plus: return "plus";
    }
    return "?";
}

std::string expression(PorterDuff op) {
    switch (op) {
        case PorterDuff::clear:
        case PorterDuff::a:
        case PorterDuff::b: return std::string(to_string(op));
        default: return "A " + std::string(to_string(op)) + " B";
    }
}

std::string format_rgba(Rgba c) {
    const auto n = [](double v) { return format_number(std::abs(v) < 1e-12 ? 0.0 : v); };
    return "(" + n(c.r) + ", " + n(c.g) + ", " + n(c.b) + ", " + n(c.a) + ")";
}

namespace {
// What the compositing machine says, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying found{"composite.found", "The ray through the image's centre passes through {count} polygons: its layers, nearest first."};
constexpr Saying premultiplied{"composite.premultiplied",
                               "Layer {layer} (polygon {id}): straight {straight}, premultiplied by α = {alpha}: {premultiplied}."};
constexpr Saying over{"composite.over",
                      "Back to front, layer {layer} over what lies behind: C′ = C_F + (1 − A_F)·C = {after}; A′ = {alpha}. The straight formula gives {straight}."};
constexpr Saying under{"composite.under",
                       "Front to back, layer {layer} under what lies in front: C′ = C + (1 − A)·C_F = {after}; A′ = {alpha}."};
constexpr Saying stop{"composite.stop",
                      "Front to back stops: A = {alpha} is opaque enough, so the {skipped} {skipped?layer|layers} from layer {layer} on cannot show."};
constexpr Saying same{"composite.same", "Both orders give {colour}: over is associative, so the order of the operations does not matter, only the layers' order."};
constexpr Saying differ{"composite.differ", "Back to front gives {back}, front to back {front}: they differ by {difference} (the early stop)."};
constexpr Saying associative{"composite.associative",
                             "(F over M) over B = {left} and F over (M over B) = {right}: premultiplied over is associative. The naive blend gives {naive_left} and {naive_right}: {verdict}."};
constexpr Saying porter_duff{"composite.porter_duff", "{op} = {fa}·A + {fb}·B = {result}."};
constexpr Saying done{"composite.done", "Done: the pixel is {colour} premultiplied, {straight} straight."};
constexpr Saying naive_associative{"composite.naive_associative", "associative here"};
constexpr Saying naive_not{"composite.naive_not", "not associative, it counts B twice"};
constexpr Saying all[] = {found, premultiplied, over, under, stop, same, differ, associative, porter_duff, done, naive_associative, naive_not};
}  // namespace say
}  // namespace

std::span<const Saying> composite_sayings() { return say::all; }

Phrase phrase(const CompositeEvent& event) {
    const auto n = [](auto v) { return std::to_string(v); };
    const auto x = [](double v) { return format_number(v); };
    return std::visit(
        overloaded{
            [&](const LayersFound& e) { return Phrase(say::found, {{"count", n(e.count)}}); },
            [&](const LayerPremultiplied& e) {
                return Phrase(say::premultiplied, {{"layer", n(e.layer)}, {"id", n(e.id)}, {"straight", format_rgba(e.straight)},
                                                   {"alpha", x(e.alpha)}, {"premultiplied", format_rgba(e.premultiplied)}});
            },
            [&](const OverApplied& e) {
                return Phrase(say::over, {{"layer", n(e.layer)}, {"after", format_rgba(e.after)}, {"alpha", x(e.alpha)},
                                          {"straight", format_rgba(e.straight_after)}});
            },
            [&](const UnderApplied& e) {
                return Phrase(say::under, {{"layer", n(e.layer)}, {"after", format_rgba(e.after)}, {"alpha", x(e.alpha)}});
            },
            [&](const EarlyStop& e) {
                return Phrase(say::stop, {{"alpha", x(e.alpha)}, {"layer", n(e.layer)}, {"skipped", n(e.skipped)}});
            },
            [&](const OrdersCompared& e) {
                if (e.same) return Phrase(say::same, {{"colour", format_rgba(e.back_to_front)}});
                return Phrase(say::differ, {{"back", format_rgba(e.back_to_front)}, {"front", format_rgba(e.front_to_back)},
                                            {"difference", x(e.difference)}});
            },
            [&](const AssociativityChecked& e) {
                const Saying& verdict = e.naive_associative ? say::naive_associative : say::naive_not;
                return Phrase(say::associative,
                              {{"left", format_rgba(e.left)}, {"right", format_rgba(e.right)}, {"naive_left", format_rgba(e.naive_left)},
                               {"naive_right", format_rgba(e.naive_right)}, {"verdict", std::string(verdict.english)}},
                              {{"verdict", &verdict}});
            },
            [&](const PorterDuffApplied& e) {
                return Phrase(say::porter_duff,
                              {{"op", expression(e.op)}, {"fa", x(e.fa)}, {"fb", x(e.fb)}, {"result", format_rgba(e.result)}});
            },
            [&](const CompositeFinished& e) {
                return Phrase(say::done, {{"colour", format_rgba(e.colour)}, {"straight", format_rgba(e.straight)}});
            },
        },
        event);
}

std::string describe(const CompositeEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
