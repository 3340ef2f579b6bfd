// SPDX-License-Identifier: MIT
#include "depth_sort/depth_sort_events.h"

#include <algorithm>
#include <cmath>

#include "core/events.h"
#include "core/overloaded.h"

namespace hsr::algo {
namespace {

std::string n(std::uint64_t v) { return std::to_string(v); }
std::string vertices(double count) { return n(std::uint64_t(count)) + (count == 1 ? " vertex" : " vertices"); }
std::string range(double a, double b) {
    const double scale = std::max(std::abs(a), std::abs(b));
    return "[" + format_number(a, scale) + ", " + format_number(b, scale) + "]";
}

}  // namespace

std::string_view to_string(OrderTest t) {
    switch (t) {
        case OrderTest::x_extents: return "1. x extents apart";
        case OrderTest::y_extents: return "2. y extents apart";
        case OrderTest::r_behind_q: return "3. R wholly behind Q's plane";
        case OrderTest::q_in_front_of_r: return "4. Q wholly in front of R's plane";
        case OrderTest::projections: return "5. projections apart";
        case OrderTest::q_behind_r: return "3'. Q wholly behind R's plane";
        case OrderTest::r_in_front_of_q: return "4'. R wholly in front of Q's plane";
    }
    return "?";
}

std::string describe(const DepthSortEvent& event) {
    return std::visit(
        overloaded{
            [](const ListSorted& e) { return "Sorted " + n(e.order.size()) + " polygons by their farthest depth, farthest first."; },
            [](const PairExamined& e) {
                return "R = #" + n(e.r) + " (z " + range(e.r_min_z, e.r_max_z) + ") and Q = #" + n(e.q) + " (z " +
                       range(e.q_min_z, e.q_max_z) + "): their z extents overlap.";
            },
            [](const TestTried& e) {
                std::string numbers;
                switch (e.test) {
                    case OrderTest::x_extents:
                    case OrderTest::y_extents: numbers = "R " + range(e.a, e.b) + ", Q " + range(e.c, e.d); break;
                    case OrderTest::projections: numbers = e.a != 0 ? "they overlap" : "a separating axis exists"; break;
                    default:
                        numbers = vertices(e.a) + " on the far side, " + vertices(e.b) + " on the viewer's side, " + vertices(e.c) +
                                  " on the plane";
                }
                return std::string(to_string(e.test)) + ": " + (e.passed ? "yes" : "no") + " (" + numbers + ").";
            },
            [](const PolygonMoved& e) { return "Q = #" + n(e.polygon) + " must be drawn before #" + n(e.ahead_of) + ": it moves to the head of the list."; },
            [](const CycleDetected& e) { return "#" + n(e.polygon) + " would move a second time: a cycle. Split instead."; },
            [](const PolygonCut& e) {
                if (e.across)
                    return "No plane of the cycle cuts another of it: split #" + n(e.polygon) +
                           " across its length, by a plane along the view rays, into #" + n(e.front) + " and #" + n(e.back) + ".";
                return "Split #" + n(e.polygon) + " by the plane of #" + n(e.by) + " into #" + n(e.front) + " and #" + n(e.back) + ".";
            },
            [](const PolygonPainted& e) {
                if (e.deferred)
                    return "#" + n(e.polygon) + " (polygon " + std::to_string(e.id) + ") joins the output list, to be drawn in the display step.";
                return "Draw #" + n(e.polygon) + " (polygon " + std::to_string(e.id) + ").";
            },
            [](const DepthSortFinished& e) {
                return "Done: " + n(e.drawn) + " drawn after " + n(e.pairs) + (e.pairs == 1 ? " pair, " : " pairs, ") + n(e.moves) +
                       (e.moves == 1 ? " move and " : " moves and ") + n(e.splits) + (e.splits == 1 ? " split." : " splits.");
            },
            [](const FrontPolygonDrawn& e) {
                return "Draw #" + n(e.polygon) + " (polygon " + std::to_string(e.id) + ") front to back: " + n(e.written) +
                       " pixels written, " + n(e.hidden) + " already written by nearer polygons; " + n(e.unwritten) +
                       " pixels still unwritten.";
            },
            [](const ScreenFilled& e) {
                return "Every pixel is written after " + n(e.drawn) + " polygons: stop; the " + n(e.left) +
                       " farther polygons are hidden and never drawn.";
            },
            [](const FrontDisplayFinished& e) {
                return "Front to back: all " + n(e.drawn) + " polygons drawn; " + n(e.unwritten) + " pixels show the background.";
            },
            [](const SortBoundReached& e) {
                return "Stopped: the bound of " + n(e.limit) + (e.bound == SortBound::splits ? " splits" : " pairs examined") + " was reached.";
            },
        },
        event);
}

}  // namespace hsr::algo
