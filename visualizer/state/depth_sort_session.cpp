// SPDX-License-Identifier: MIT
#include "state/depth_sort_session.h"

#include <algorithm>

#include "core/overloaded.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

const Pseudocode<DepthSortEvent> sort_lines = {
    {"DepthSort(polygonDB):", {}},
    {"  for each polygon find MINZ and MAXZ; sort, farthest first", {step<ListSorted>()}},
    {"  R = head of the list; for each Q whose z extent overlaps R's:", {step<PairExamined>()}},
    {"    1. x extents apart?   2. y extents apart?", {micro<TestTried>([](const TestTried& e) { return e.test == OrderTest::x_extents || e.test == OrderTest::y_extents; })}},
    {"    3. R wholly behind Q's plane?", {micro<TestTried>([](const TestTried& e) { return e.test == OrderTest::r_behind_q; })}},
    {"    4. Q wholly in front of R's plane?", {micro<TestTried>([](const TestTried& e) { return e.test == OrderTest::q_in_front_of_r; })}},
    {"    5. projections apart?", {micro<TestTried>([](const TestTried& e) { return e.test == OrderTest::projections; })}},
    {"    else swap roles, retry 3 and 4:", {micro<TestTried>()}},
    {"      Q must go first: move Q to the head", {step<PolygonMoved>()}},
    {"      Q moved before (a cycle), or no order:", {step<CycleDetected>()}},
    {"        split R by the plane of Q (else Q by R's)", {step<PolygonCut>(), step<SortBoundReached>()}},
    {"  no Q left: draw R (back to front)", {step<PolygonPainted>(), step<DepthSortFinished>()}},
    {"  or display front to back: the nearest first,", {}},
    {"    each on the pixels no nearer one has written", {step<FrontPolygonDrawn>(), step<FrontDisplayFinished>()}},
    {"    every pixel written: stop, the rest are hidden", {step<ScreenFilled>()}},
};

}  // namespace

DepthSortSession::RunType DepthSortSession::machine(const Lesson& lesson) {
    std::vector<SortPolygon> polygons = sort_polygons(lesson.scene);
    DepthSortView initial;
    initial.polygons = polygons;
    DepthSortOptions o;
    if (lesson.front_to_back) o.front_to_back = lesson.grid;
    return {depth_sort(std::move(polygons), o), std::move(initial)};
}

void reduce(DepthSortView& v, const DepthSortEvent& event) {
    std::visit(overloaded{
                   [&](const ListSorted& e) { v.list = e.order; },
                   [&](const PairExamined& e) {
                       v.r = int(e.r), v.q = int(e.q), v.tests.clear(), v.moved = v.cycle = v.cut = -1;
                   },
                   [&](const TestTried& e) { v.tests.push_back(e); },
                   [&](const PolygonMoved& e) {
                       std::erase(v.list, e.polygon);
                       v.list.insert(v.list.begin(), e.polygon);
                       v.moved = int(e.polygon), ++v.moves;
                   },
                   [&](const CycleDetected& e) { v.cycle = int(e.polygon); },
                   [&](const PolygonCut& e) {
                       const SortPolygon whole = v.polygons[e.polygon];  // a copy: push_back may move the list
                       v.polygons.push_back({whole.id, whole.color, e.front_vertices, whole.opacity});
                       v.polygons.push_back({whole.id, whole.color, e.back_vertices, whole.opacity});
                       const auto at = std::find(v.list.begin(), v.list.end(), e.polygon);
                       if (at != v.list.end()) {
                           *at = e.back;
                           v.list.insert(at + 1, e.front);
                       }
                       v.cut = int(e.polygon), ++v.splits;
                   },
                   [&](const PolygonPainted& e) {
                       std::erase(v.list, e.polygon);
                       v.drawn.push_back(e.polygon);
                       v.front_to_back = e.deferred;
                       v.r = v.q = -1, v.tests.clear();
                   },
                   [&](const DepthSortFinished&) { v.done = true; },
                   [&](const SortBoundReached&) { v.bounded = true; },
                   [&](const FrontPolygonDrawn& e) { v.front.push_back(e.polygon), v.unwritten = e.unwritten; },
                   [&](const ScreenFilled& e) { v.screen_filled = true, v.left = e.left; },
                   [&](const FrontDisplayFinished& e) { v.unwritten = e.unwritten; },
               },
               event);
}

algo::Image painted_so_far(const DepthSortView& v, algo::Viewport size) {
    algo::Image image(size.width, size.height, {26, 28, 33});
    // front to back, each pixel written once by the nearest: the same picture as painting those drawn so far from
    // the farthest of them forward
    const std::vector<std::uint32_t> order = v.front_to_back ? std::vector<std::uint32_t>(v.front.rbegin(), v.front.rend()) : v.drawn;
    for (std::uint32_t i : order) {
        std::vector<glm::dvec4> ndc;
        for (const auto& p : v.polygons[i].vertices) ndc.emplace_back(p, 1.0);
        algo::paint_clip_polygon(image, std::move(ndc), v.polygons[i].id, v.polygons[i].color, v.polygons[i].opacity);
    }
    return image;
}

std::size_t approx_bytes(const DepthSortView& v) {
    std::size_t b = sizeof(DepthSortView) + (v.list.capacity() + v.drawn.capacity()) * sizeof(std::uint32_t) +
                    v.tests.capacity() * sizeof(TestTried);
    for (const auto& p : v.polygons) b += sizeof(SortPolygon) + p.vertices.capacity() * sizeof(Vec3);
    return b;
}

DepthSortSession::DepthSortSession(Lesson lesson, PlayerOptions options) : PlayerSession(lesson, machine(lesson), options) {}

std::string DepthSortSession::sentence_of(const DepthSortEvent& e, const DepthSortView&) { return describe(e); }
std::string DepthSortSession::describe_event(const DepthSortEvent& e) const { return sentence_of(e, view()); }
std::string DepthSortSession::speak_event(const DepthSortEvent& e) const { return window_strings().say(phrase(e)); }

const Pseudocode<DepthSortEvent>& DepthSortSession::table() const { return sort_lines; }

const FamilyFacts DepthSortSession::facts = {
    .topic = "Depth sort",
    .speaks_to = [](const algo::Scene& s, const algo::AlgorithmInfo&) { return expects_from_renderer(s, "depth-sort"); },
    .random_scene = &random_triangle_scene,
    .measure = &analysis::measure_hidden_surfaces,
};

}  // namespace hsr::viz
