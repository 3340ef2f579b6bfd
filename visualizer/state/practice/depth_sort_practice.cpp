// SPDX-License-Identifier: MIT
// Practice for Newell's depth sort: two triangles on the fat-pixel grid, each corner at its own depth, seen along
// the depth axis. The one reaching farthest heads the list (R); the other overlaps it in depth (Q). Which of the
// notes' tests first settles the pair: 1. x extents apart, 2. y extents apart, 3. R wholly behind Q's plane, 4. Q
// wholly in front of R's plane, 5. projections apart; or, the roles swapped, 3 or 4 says Q must go first; or nothing
// does and a triangle is split? Every answer is an event of the depth-sort lesson's own machine on the scene.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "depth_sort/depth_sort.h"
#include "state/practice/pixel_triangles.h"
#include "core/okabe_ito.h"

namespace hsr::viz::practice {
namespace {

using glm::dvec2;
using glm::dvec3;

struct SortTriangle {
    dvec3 corner[3];  // pixel x, pixel y (down), depth (away from the eye)
};

// Corners on whole pixels (easy) or on a half-pixel grid; depths 2 … 9 in steps of 1 (easy) or 0.5. Hard draws the
// second triangle around the first's middle, so that extents overlap and the planes or the split must decide.
SortTriangle draw_triangle(Dice& d, Level l, std::optional<dvec2> around) {
    const double step = l == Level::easy ? 1 : 0.5;
    SortTriangle t{};
    for (dvec3& c : t.corner) {
        if (around)
            c = {std::clamp(around->x + d.grid(-8, 8, step), 1.0, 31.0), std::clamp(around->y + d.grid(-6, 6, step), 1.0, 23.0), 0};
        else
            c = {d.grid(1, pixel_grid.width - 1, step), d.grid(1, pixel_grid.height - 1, step), 0};
        c.z = d.grid(2, 9, step);
    }
    return t;
}

double min_of(const SortTriangle& t, int axis) { return std::min({t.corner[0][axis], t.corner[1][axis], t.corner[2][axis]}); }
double max_of(const SortTriangle& t, int axis) { return std::max({t.corner[0][axis], t.corner[1][axis], t.corner[2][axis]}); }

dvec3 normal_of(const SortTriangle& t) { return glm::cross(t.corner[1] - t.corner[0], t.corner[2] - t.corner[0]); }

// How far the projections are apart along the best separating axis (negative: they overlap by that much).
double projection_gap(const SortTriangle& a, const SortTriangle& b) {
    double gap = -1e300;
    for (const SortTriangle* t : {&a, &b})
        for (int k = 0; k < 3; ++k) {
            const dvec2 e = dvec2(t->corner[(k + 1) % 3]) - dvec2(t->corner[k]);
            const dvec2 axis = glm::normalize(dvec2(-e.y, e.x));
            double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
            for (int s = 0; s < 2; ++s)
                for (const dvec3& c : (s == 0 ? a : b).corner) {
                    lo[s] = std::min(lo[s], glm::dot(axis, dvec2(c))), hi[s] = std::max(hi[s], glm::dot(axis, dvec2(c)));
                }
            gap = std::max({gap, lo[1] - hi[0], lo[0] - hi[1]});
        }
    return gap;
}

// A draw is fair when no number the tests compare sits a hair from its threshold: planes not along the view rays,
// no corner within 0.05 of the other's plane unless on it, projections apart or overlapping by more than 0.05.
bool fair(const SortTriangle& a, const SortTriangle& b) {
    for (const auto& [t, other] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
        const dvec3 n = normal_of(*t);
        if (std::abs(n.z) < 8 || std::abs(n.z) < 0.05 * glm::length(n)) return false;  // under 4 px² on screen, or edge-on
        for (const dvec3& c : other->corner) {
            const double distance = glm::dot(n, c - t->corner[0]) / glm::length(n);
            if (distance != 0 && std::abs(distance) < 0.05) return false;
        }
    }
    if (std::abs(projection_gap(a, b)) < 0.05) return false;
    if (max_of(a, 2) == max_of(b, 2)) return false;  // one must reach farthest, to head the list
    return std::min(max_of(a, 2), max_of(b, 2)) - std::max(min_of(a, 2), min_of(b, 2)) >= 0.5;  // overlap in depth
}

algo::Scene scene_of(const SortTriangle (&t)[2]) {
    static const algo::Color colours[] = {algo::okabe_ito::as<algo::Color>(algo::okabe_ito::orange), algo::okabe_ito::as<algo::Color>(algo::okabe_ito::sky_blue)};
    algo::Scene scene = pixel_grid_scene("two triangles for the depth sort");
    for (std::size_t k = 0; k < 2; ++k) {
        algo::ScenePolygon p{algo::SceneId(k + 1), colours[k], {}};
        for (const dvec3& c : t[k].corner) p.vertices.push_back(pixel_point(dvec2(c), c.z));
        scene.polygons.push_back(p);
    }
    return scene;
}

std::string triangle_text(const SortTriangle& t) {
    std::string s = "(";
    for (int c = 0; c < 3; ++c)
        s += (c ? ", " : "") + std::string("(") + number_text(t.corner[c].x) + ", " + number_text(t.corner[c].y) + ", " +
             number_text(t.corner[c].z) + ")";
    return s + ")";
}

// What the question says, each template once (the catalogues' [exercise.depth_sort] translate them).
namespace say {
using algo::Saying;
constexpr Saying settling{"depth_sort.settling",
                          "Newell's depth sort, looking along the depth axis: triangle 1 (#0 in the list) {triangle_1} and "
                          "triangle 2 (#1) {triangle_2}, corners as (x, y, depth) on the 32 × 24 grid, x to the right, y down, "
                          "depth growing away from the eye. Triangle {r} reaches farthest and heads the list: it is R, and "
                          "triangle {q} (Q) overlaps it in depth. Which test first settles the pair?"};
constexpr Saying test_1{"depth_sort.test_1", "test 1: the x extents are apart"};
constexpr Saying test_2{"depth_sort.test_2", "test 2: the y extents are apart"};
constexpr Saying test_3{"depth_sort.test_3", "test 3: R is wholly behind Q's plane"};
constexpr Saying test_4{"depth_sort.test_4", "test 4: Q is wholly in front of R's plane"};
constexpr Saying test_5{"depth_sort.test_5", "test 5: the projections are apart"};
constexpr Saying swapped{"depth_sort.swapped", "swapped, 3 or 4 holds: Q moves ahead of R"};
constexpr Saying split{"depth_sort.split", "none: a triangle is split by the other's plane"};
constexpr Saying all[] = {settling, test_1, test_2, test_3, test_4, test_5, swapped, split};
}  // namespace say

std::optional<Exercise> settling_exercise(Dice& d, Level l) {
    SortTriangle t[2];
    t[0] = draw_triangle(d, l, std::nullopt);
    const dvec2 middle = (dvec2(t[0].corner[0]) + dvec2(t[0].corner[1]) + dvec2(t[0].corner[2])) / 3.0;
    t[1] = draw_triangle(d, l, l == Level::hard ? std::optional(glm::round(middle)) : std::nullopt);
    if (!fair(t[0], t[1])) return std::nullopt;
    algo::Scene scene = scene_of(t);
    std::vector<algo::SortPolygon> polygons = algo::sort_polygons(scene);
    if (polygons.size() != 2) return std::nullopt;
    std::vector<algo::DepthSortEvent> events;
    auto machine = algo::depth_sort(std::move(polygons));
    while (const algo::DepthSortEvent* e = machine.next()) events.push_back(*e);
    // the first pair examined, and the event that settles it: a test that passes, a move, or a cut
    std::optional<std::size_t> pair, settled;
    std::size_t answer = 0;
    for (std::size_t step = 0; step < events.size() && !settled; ++step) {
        if (std::holds_alternative<algo::PairExamined>(events[step])) pair = step;
        if (!pair) continue;
        if (const auto* test = std::get_if<algo::TestTried>(&events[step]); test && test->passed)
            settled = step, answer = std::min(std::size_t(test->test), std::size_t(5));
        if (std::holds_alternative<algo::PolygonCut>(events[step])) settled = step, answer = 6;
    }
    if (!pair || !settled) return std::nullopt;
    // Triangles drawn at random pierce each other half the time: keep a third of those (half at the hard level),
    // so that every test has its turn.
    if (answer == 6 && d.below(l == Level::hard ? 2 : 3) != 0) return std::nullopt;
    const auto& examined = std::get<algo::PairExamined>(events[*pair]);
    const std::size_t r = examined.r + 1, q = examined.q + 1;
    Exercise e;
    e.ask(Wording(say::settling, {{"triangle_1", triangle_text(t[0])},
                                  {"triangle_2", triangle_text(t[1])},
                                  {"r", std::to_string(r)},
                                  {"q", std::to_string(q)}}));
    // in the order of the tests (answer: the test's number − 1, the swapped tests 5, a cut 6)
    e.offer({Wording(say::test_1), Wording(say::test_2), Wording(say::test_3), Wording(say::test_4), Wording(say::test_5),
             Wording(say::swapped), Wording(say::split)},
            answer);
    e.deciding = algo::describe(events[*settled]);
    e.deciding_step = *settled;
    e.hold_at = *pair;
    nlohmann::json triangles = nlohmann::json::array();
    for (const SortTriangle& k : t)
        triangles.push_back({{k.corner[0].x, k.corner[0].y, k.corner[0].z}, {k.corner[1].x, k.corner[1].y, k.corner[1].z},
                             {k.corner[2].x, k.corner[2].y, k.corner[2].z}});
    e.given = {{"kind", "settling_test"}, {"triangles", triangles}, {"r", r}, {"q", q}};
    e.scene = std::move(scene);
    e.algorithm = "depth_sort";
    return e;
}

}  // namespace

std::vector<Topic> depth_sort_topics() {
    return {{"depthsort", "Depth sort: which test settles a pair", {"depth_sort"}, [](Draw draw) {
                 Dice d(draw.seed);
                 return settling_exercise(d, draw.level);
             },
             {say::all}}};
}

}  // namespace hsr::viz::practice
