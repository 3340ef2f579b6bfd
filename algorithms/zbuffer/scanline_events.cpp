// SPDX-License-Identifier: MIT
#include "zbuffer/scanline_events.h"

#include "core/events.h"
#include "core/overloaded.h"

namespace hsr::algo {

std::string describe(const ScanLineEvent& event) {
    const auto n = [](auto v) { return std::to_string(v); };
    return std::visit(
        overloaded{
            [&](const EdgeTableBuilt& e) {
                return "Edge table: " + n(e.edges) + " non-horizontal edges of " + n(e.polygons) +
                       " polygons, bucketed by the first scan line they cross.";
            },
            [&](const ScanLineStarted& e) { return "Scan line " + n(e.y) + "."; },
            [&](const EdgeEntered& e) {
                return "Edge " + n(e.edge) + " of polygon #" + n(e.polygon) + " enters the active edge table at x = " +
                       format_number(e.x) + ".";
            },
            [&](const EdgeLeft& e) {
                return "Edge " + n(e.edge) + " of polygon #" + n(e.polygon) + " has ended: it leaves the active edge table.";
            },
            [&](const EdgeCrossed& e) {
                return "At x = " + format_number(e.x) + " edge " + n(e.edge) + ": polygon #" + n(e.polygon) +
                       (e.entering ? " is now in." : " is now out; its span goes through the line's z-buffer.");
            },
            [&](const SpanColored& e) {
                return "Line " + n(e.y) + ", pixels " + n(e.x_begin) + " to " + n(e.x_end - 1) + ": " +
                       (e.polygon < 0 ? std::string("background") : "polygon " + n(e.id)) + ".";
            },
            [&](const ScanFinished& e) { return "Done: " + n(e.lines) + " scan lines, " + n(e.spans) + " spans."; },
            [&](const ScanStepBoundReached& e) {
                return "Stopped: the step bound of " + n(e.max_crossings) + " edge crossings was reached.";
            },
        },
        event);
}

}  // namespace hsr::algo
