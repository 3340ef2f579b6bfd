// SPDX-License-Identifier: MIT
#include "zbuffer/scanline_events.h"

#include "core/events.h"
#include "core/overloaded.h"
#include "core/phrase.h"

namespace hsr::algo {

namespace {
// What the scan-line machine says, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying table{"scanline.table",
                       "Edge table: {edges} non-horizontal edges of {polygons} polygons, bucketed by the first scan line they cross."};
constexpr Saying line{"scanline.line", "Scan line {y}."};
constexpr Saying entered{"scanline.entered", "Edge {edge} of polygon #{polygon} enters the active edge table at x = {x}."};
constexpr Saying left{"scanline.left", "Edge {edge} of polygon #{polygon} has ended: it leaves the active edge table."};
constexpr Saying in{"scanline.in", "At x = {x} edge {edge}: polygon #{polygon} is now in."};
constexpr Saying out{"scanline.out", "At x = {x} edge {edge}: polygon #{polygon} is now out; its span goes through the line's z-buffer."};
constexpr Saying classic_out{"scanline.classic_out", "At x = {x} edge {edge}: polygon #{polygon} is now out."};
constexpr Saying compared{"scanline.compared",
                          "At x = {x}, {in} polygons are in: by their plane equations #{nearest} is nearest (depth {depth}; #{next}: {next_depth}). Its colour goes up to the next intersection."};
constexpr Saying pierced{"scanline.pierced",
                         "Polygons #{was} and #{now} pierce each other at x = {x}, before the next intersection: an extra intersection there, and #{now} is nearer from pixel {pixel} on."};
constexpr Saying background{"scanline.background", "Line {y}, pixels {first} to {last}: background."};
constexpr Saying coloured{"scanline.coloured", "Line {y}, pixels {first} to {last}: polygon #{polygon}."};
constexpr Saying done{"scanline.done", "Done: {lines} scan lines, {spans} spans."};
constexpr Saying bound{"scanline.bound", "Stopped: the step bound of {limit} edge crossings was reached."};
constexpr Saying all[] = {table, line, entered, left, in, out, classic_out, compared, pierced, background, coloured, done, bound};
}  // namespace say
}  // namespace

std::span<const Saying> scanline_sayings() { return say::all; }

Phrase phrase(const ScanLineEvent& event) {
    const auto n = [](auto v) { return std::to_string(v); };
    return std::visit(
        overloaded{
            [&](const EdgeTableBuilt& e) { return Phrase(say::table, {{"edges", n(e.edges)}, {"polygons", n(e.polygons)}}); },
            [&](const ScanLineStarted& e) { return Phrase(say::line, {{"y", n(e.y)}}); },
            [&](const EdgeEntered& e) {
                return Phrase(say::entered, {{"edge", n(e.edge)}, {"polygon", n(e.polygon)}, {"x", format_number(e.x)}});
            },
            [&](const EdgeLeft& e) { return Phrase(say::left, {{"edge", n(e.edge)}, {"polygon", n(e.polygon)}}); },
            [&](const EdgeCrossed& e) {
                return Phrase(e.entering ? say::in : e.classic ? say::classic_out : say::out,
                              {{"x", format_number(e.x)}, {"edge", n(e.edge)}, {"polygon", n(e.polygon)}});
            },
            [&](const DepthsCompared& e) {
                return Phrase(say::compared, {{"x", format_number(e.x)}, {"in", n(e.in)}, {"nearest", n(e.nearest)},
                                              {"depth", format_number(e.depth)}, {"next", n(e.next)}, {"next_depth", format_number(e.next_depth)}});
            },
            [&](const PiercingFound& e) {
                return Phrase(say::pierced, {{"was", n(e.was)}, {"now", n(e.now)}, {"x", format_number(e.x)}, {"pixel", n(e.pixel)}});
            },
            [&](const SpanColored& e) {
                return Phrase(e.polygon < 0 ? say::background : say::coloured,
                              {{"y", n(e.y)}, {"first", n(e.x_begin)}, {"last", n(e.x_end - 1)}, {"polygon", n(e.polygon)}});
            },
            [&](const ScanFinished& e) { return Phrase(say::done, {{"lines", n(e.lines)}, {"spans", n(e.spans)}}); },
            [&](const ScanStepBoundReached& e) { return Phrase(say::bound, {{"limit", n(e.max_crossings)}}); },
        },
        event);
}

std::string describe(const ScanLineEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
