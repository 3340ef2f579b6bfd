// SPDX-License-Identifier: MIT
#include "abuffer/abuffer_events.h"

#include <cmath>

#include "core/events.h"
#include "core/overloaded.h"

namespace hsr::algo {

namespace {
// What the A-buffer says, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying started{"abuffer.started", "A-buffer, {width} × {height} pixels, {bits} sub-samples ({m} × {m}) per pixel: {polygons} polygons to scan into fragment lists."};
constexpr Saying fragment{"abuffer.fragment", "Polygon {polygon} at pixel ({x}, {y}): it covers {covered} of {bits} sub-samples; a fragment at depth {depth} joins the pixel's list."};
constexpr Saying scanned{"abuffer.scanned", "Polygon {polygon} scanned: {fragments} {fragments?fragment|fragments}, opacity {opacity}."};
constexpr Saying missed{"abuffer.missed", "Polygon {polygon} covers no sub-sample of any pixel (outside the view, or thinner than the sub-samples): no fragment."};
constexpr Saying resolved_fragment{"abuffer.resolved_fragment", "Pixel ({x}, {y}), fragment {order} (polygon {polygon}): {shown} of its {covered} sub-samples still let light through; it adds {percent}% of the pixel's colour."};
constexpr Saying hidden_fragment{"abuffer.hidden_fragment", "Pixel ({x}, {y}), fragment {order} (polygon {polygon}): all {covered} of its sub-samples are behind opaque fragments in front. It adds nothing."};
constexpr Saying pixel{"abuffer.pixel", "Pixel ({x}, {y}) resolved from {fragments} {fragments?fragment|fragments}: {coverage}% covered, colour ({r}, {g}, {b})."};
constexpr Saying done{"abuffer.done", "Done: {fragments} fragments on {pixels} pixels, the longest list {longest}."};
constexpr Saying bound{"abuffer.bound", "Stopped: the step bound of {fragments} fragments was reached."};
constexpr Saying all[] = {started, fragment, scanned, missed, resolved_fragment, hidden_fragment, pixel, done, bound};
}  // namespace say
}  // namespace

std::span<const Saying> abuffer_sayings() { return say::all; }

Phrase phrase(const ABufferEvent& event) {
    const auto n = [](auto v) { return std::to_string(v); };
    const auto f = [](double v) { return format_number(v); };
    const auto percent = [](double v) { return format_number(std::round(1000 * v) / 10); };
    return std::visit(
        overloaded{
            [&](const ABufferStarted& e) {
                return Phrase(say::started, {{"width", n(e.width)}, {"height", n(e.height)}, {"bits", n(e.mask_size * e.mask_size)},
                                             {"m", n(e.mask_size)}, {"polygons", n(e.polygons)}});
            },
            [&](const FragmentMade& e) {
                return Phrase(say::fragment, {{"polygon", n(e.polygon)}, {"x", n(e.x)}, {"y", n(e.y)}, {"covered", n(e.covered)},
                                              {"bits", n(e.samples)}, {"depth", f(e.depth)}});
            },
            [&](const PolygonScanned& e) {
                if (e.fragments == 0) return Phrase(say::missed, {{"polygon", n(e.polygon)}});
                return Phrase(say::scanned, {{"polygon", n(e.polygon)}, {"fragments", n(e.fragments)}, {"opacity", f(e.opacity)}});
            },
            [&](const FragmentResolved& e) {
                if (e.shown == 0)
                    return Phrase(say::hidden_fragment, {{"x", n(e.x)}, {"y", n(e.y)}, {"order", n(e.order)}, {"polygon", n(e.polygon)}, {"covered", n(e.covered)}});
                return Phrase(say::resolved_fragment, {{"x", n(e.x)}, {"y", n(e.y)}, {"order", n(e.order)}, {"polygon", n(e.polygon)},
                                                       {"shown", n(e.shown)}, {"covered", n(e.covered)}, {"percent", percent(e.weight)}});
            },
            [&](const PixelResolved& e) {
                return Phrase(say::pixel, {{"x", n(e.x)}, {"y", n(e.y)}, {"fragments", n(e.fragments)}, {"coverage", percent(e.a)},
                                           {"r", f(e.r)}, {"g", f(e.g)}, {"b", f(e.b)}});
            },
            [&](const ABufferFinished& e) {
                if (e.bounded) return Phrase(say::bound, {{"fragments", n(e.fragments)}});
                return Phrase(say::done, {{"fragments", n(e.fragments)}, {"pixels", n(e.pixels)}, {"longest", n(e.longest_list)}});
            },
        },
        event);
}

std::string describe(const ABufferEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
