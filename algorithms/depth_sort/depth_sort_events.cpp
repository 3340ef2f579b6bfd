// SPDX-License-Identifier: MIT
#include "depth_sort/depth_sort_events.h"

#include <algorithm>
#include <cmath>

#include "core/events.h"
#include "core/overloaded.h"
#include "core/phrase.h"

namespace hsr::algo {
namespace {

std::string n(std::uint64_t v) { return std::to_string(v); }
std::string count(double v) { return n(std::uint64_t(v)); }
std::string range(double a, double b) {
    const double scale = std::max(std::abs(a), std::abs(b));
    return "[" + format_number(a, scale) + ", " + format_number(b, scale) + "]";
}

// What the machine says, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying test_1{"depth_sort.test_1", "1. x extents apart"};
constexpr Saying test_2{"depth_sort.test_2", "2. y extents apart"};
constexpr Saying test_3{"depth_sort.test_3", "3. R wholly behind Q's plane"};
constexpr Saying test_4{"depth_sort.test_4", "4. Q wholly in front of R's plane"};
constexpr Saying test_5{"depth_sort.test_5", "5. projections apart"};
constexpr Saying test_3_swapped{"depth_sort.test_3_swapped", "3'. Q wholly behind R's plane"};
constexpr Saying test_4_swapped{"depth_sort.test_4_swapped", "4'. R wholly in front of Q's plane"};
constexpr Saying yes{"depth_sort.yes", "yes"};
constexpr Saying no{"depth_sort.no", "no"};
constexpr Saying sorted{"depth_sort.sorted", "Sorted {polygons} polygons by their farthest depth, farthest first."};
constexpr Saying pair{"depth_sort.pair", "R = #{r} (z {r_z}) and Q = #{q} (z {q_z}): their z extents overlap."};
constexpr Saying extents{"depth_sort.extents_tried", "{test}: {verdict} (R {r}, Q {q})."};
constexpr Saying projections_overlap{"depth_sort.projections_overlap", "{test}: {verdict} (they overlap)."};
constexpr Saying projections_apart{"depth_sort.projections_apart", "{test}: {verdict} (a separating axis exists)."};
constexpr Saying sides{"depth_sort.sides_tried",
                       "{test}: {verdict} ({far} {far?vertex|vertices} on the far side, {near} {near?vertex|vertices} on the "
                       "viewer's side, {on} {on?vertex|vertices} on the plane)."};
constexpr Saying moved{"depth_sort.moved", "Q = #{q} must be drawn before #{ahead}: it moves to the head of the list."};
constexpr Saying cycle{"depth_sort.cycle", "#{polygon} would move a second time: a cycle. Split instead."};
constexpr Saying cut_across{"depth_sort.cut_across",
                            "No plane of the cycle cuts another of it: split #{polygon} across its length, by a plane along "
                            "the view rays, into #{front} and #{back}."};
constexpr Saying cut{"depth_sort.cut", "Split #{polygon} by the plane of #{by} into #{front} and #{back}."};
constexpr Saying deferred{"depth_sort.deferred", "#{polygon} joins the output list, to be drawn in the display step."};
constexpr Saying painted{"depth_sort.painted", "Draw #{polygon}."};
constexpr Saying finished{"depth_sort.finished",
                          "Done: {drawn} {drawn?polygon|polygons} in depth order after {pairs} {pairs?pair|pairs}, {moves} "
                          "{moves?move|moves} and {splits} {splits?split|splits}."};
constexpr Saying front_drawn{"depth_sort.front_drawn",
                             "Draw #{polygon} front to back: {written} pixels written, {hidden} already "
                             "written by nearer polygons; {unwritten} pixels still unwritten."};
constexpr Saying screen_filled{"depth_sort.screen_filled",
                               "Every pixel is written after {drawn} polygons: stop; the {left} farther polygons are hidden "
                               "and never drawn."};
constexpr Saying front_finished{"depth_sort.front_finished",
                                "Front to back: all {drawn} polygons drawn; {unwritten} pixels show the background."};
constexpr Saying bound_splits{"depth_sort.bound_splits", "Stopped: the bound of {limit} splits was reached."};
constexpr Saying bound_pairs{"depth_sort.bound_pairs", "Stopped: the bound of {limit} pairs examined was reached."};
constexpr Saying all[] = {test_1, test_2, test_3, test_4, test_5, test_3_swapped, test_4_swapped, yes, no, sorted, pair, extents,
                          projections_overlap, projections_apart, sides, moved, cycle, cut_across, cut, deferred, painted,
                          finished, front_drawn, screen_filled, front_finished, bound_splits, bound_pairs};
}  // namespace say
}  // namespace

const Saying& term(OrderTest t) {
    switch (t) {
        case OrderTest::x_extents: return say::test_1;
        case OrderTest::y_extents: return say::test_2;
        case OrderTest::r_behind_q: return say::test_3;
        case OrderTest::q_in_front_of_r: return say::test_4;
        case OrderTest::projections: return say::test_5;
        case OrderTest::q_behind_r: return say::test_3_swapped;
        case OrderTest::r_in_front_of_q: return say::test_4_swapped;
    }
    return say::test_1;
}

std::string_view to_string(OrderTest t) { return term(t).english; }

std::span<const Saying> depth_sort_sayings() { return say::all; }

Phrase phrase(const DepthSortEvent& event) {
    return std::visit(
        overloaded{
            [](const ListSorted& e) { return Phrase(say::sorted, {{"polygons", n(e.order.size())}}); },
            [](const PairExamined& e) {
                return Phrase(say::pair, {{"r", n(e.r)}, {"r_z", range(e.r_min_z, e.r_max_z)}, {"q", n(e.q)}, {"q_z", range(e.q_min_z, e.q_max_z)}});
            },
            [](const TestTried& e) {
                const Terms terms = {{"test", &term(e.test)}, {"verdict", e.passed ? &say::yes : &say::no}};
                switch (e.test) {
                    case OrderTest::x_extents:
                    case OrderTest::y_extents: return Phrase(say::extents, {{"r", range(e.a, e.b)}, {"q", range(e.c, e.d)}}, terms);
                    case OrderTest::projections: return Phrase(e.a != 0 ? say::projections_overlap : say::projections_apart, {}, terms);
                    default: return Phrase(say::sides, {{"far", count(e.a)}, {"near", count(e.b)}, {"on", count(e.c)}}, terms);
                }
            },
            [](const PolygonMoved& e) { return Phrase(say::moved, {{"q", n(e.polygon)}, {"ahead", n(e.ahead_of)}}); },
            [](const CycleDetected& e) { return Phrase(say::cycle, {{"polygon", n(e.polygon)}}); },
            [](const PolygonCut& e) {
                if (e.across) return Phrase(say::cut_across, {{"polygon", n(e.polygon)}, {"front", n(e.front)}, {"back", n(e.back)}});
                return Phrase(say::cut, {{"polygon", n(e.polygon)}, {"by", n(e.by)}, {"front", n(e.front)}, {"back", n(e.back)}});
            },
            [](const PolygonPainted& e) {
                return Phrase(e.deferred ? say::deferred : say::painted, {{"polygon", n(e.polygon)}, {"id", std::to_string(e.id)}});
            },
            [](const DepthSortFinished& e) {
                return Phrase(say::finished, {{"drawn", n(e.drawn)}, {"pairs", n(e.pairs)}, {"moves", n(e.moves)}, {"splits", n(e.splits)}});
            },
            [](const FrontPolygonDrawn& e) {
                return Phrase(say::front_drawn, {{"polygon", n(e.polygon)}, {"id", std::to_string(e.id)}, {"written", n(e.written)},
                                                 {"hidden", n(e.hidden)}, {"unwritten", n(e.unwritten)}});
            },
            [](const ScreenFilled& e) { return Phrase(say::screen_filled, {{"drawn", n(e.drawn)}, {"left", n(e.left)}}); },
            [](const FrontDisplayFinished& e) { return Phrase(say::front_finished, {{"drawn", n(e.drawn)}, {"unwritten", n(e.unwritten)}}); },
            [](const SortBoundReached& e) {
                return Phrase(e.bound == SortBound::splits ? say::bound_splits : say::bound_pairs, {{"limit", n(e.limit)}});
            },
        },
        event);
}

std::string describe(const DepthSortEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
