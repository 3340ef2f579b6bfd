// SPDX-License-Identifier: MIT
#include "state/zmerge_session.h"

#include "core/overloaded.h"
#include "state/long_work.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

const Pseudocode<ZMergeEvent> merge_lines = {
    {"for (x = 0; x < XRES; x++)", {}},
    {"  for (y = 0; y < YRES; y++) {", {}},
    {"    Fc[x, y] = (Za[x, y] nearer than Zb[x, y]) ? Fa[x, y] : Fb[x, y];", {step<PixelMerged>([](const PixelMerged& e) { return e.y == 0; }), micro<PixelMerged>()}},
    {"    Zc[x, y] = (Za[x, y] nearer than Zb[x, y]) ? Za[x, y] : Zb[x, y];", {}},
    {"  }", {step<MergeFinished>()}},
    {"/* nearer: a smaller code here; the lecture's depths fall with distance */", {}},
};

}  // namespace

ZMergeView zmerge_initial_view(const Lesson& lesson) {
    const Scene scene = grid_scene(lesson);
    auto all = std::make_shared<const std::vector<ScreenPolygon>>(project_polygons(scene, lesson.grid));
    const std::size_t half = (all->size() + 1) / 2;
    const ZBufferOptions o = zbuffer_options(scene, lesson.grid, lesson.depth_format, EventDetail::polygon);
    auto a = std::make_shared<const FrameDepth>(LongWork::run_to_end(zbuffer_fill({all->begin(), all->begin() + std::ptrdiff_t(half)}, o)));
    auto b = std::make_shared<const FrameDepth>(LongWork::run_to_end(zbuffer_fill({all->begin() + std::ptrdiff_t(half), all->end()}, o)));
    ZMergeView initial;
    initial.viewport = lesson.grid;
    initial.polygons = all;
    initial.a = a, initial.b = b, initial.b_offset = half;
    initial.merged.assign(a->polygon.size(), -2);
    return initial;
}

namespace {

}  // namespace

ZMergeSession::RunType ZMergeSession::machine(const Lesson& lesson) {
    ZMergeView initial = zmerge_initial_view(lesson);
    auto merge = z_merge_steps(*initial.a, *initial.b);
    return {std::move(merge), std::move(initial)};
}

void reduce(ZMergeView& v, const ZMergeEvent& event) {
    std::visit(overloaded{
                   [&](const PixelMerged& e) {
                       const std::size_t k = std::size_t(e.y) * std::size_t(v.viewport.width) + std::size_t(e.x);
                       const std::int32_t from_b = v.b->polygon[k] < 0 ? -1 : v.b->polygon[k] + std::int32_t(v.b_offset);
                       v.merged[k] = e.from_a ? v.a->polygon[k] : from_b;
                       v.x = e.x, v.y = e.y, v.depth_a = e.depth_a, v.depth_b = e.depth_b, v.from_a = e.from_a;
                       ++(e.from_a ? v.from_a_count : from_b < 0 ? v.background_count : v.from_b_count);
                   },
                   [&](const MergeFinished&) { v.done = true, v.x = v.y = -1; },
               },
               event);
}

std::size_t approx_bytes(const ZMergeView& v) { return sizeof(ZMergeView) + v.merged.capacity() * sizeof(std::int32_t); }

ZMergeSession::ZMergeSession(Lesson lesson, PlayerOptions options) : PlayerSession(lesson, machine(lesson), options) {}

std::string ZMergeSession::sentence_of(const ZMergeEvent& e, const ZMergeView&) { return describe(e); }
std::string ZMergeSession::describe_event(const ZMergeEvent& e) const { return sentence_of(e, view()); }
std::string ZMergeSession::speak_event(const ZMergeEvent& e) const { return window_strings().say(phrase(e)); }

const Pseudocode<ZMergeEvent>& ZMergeSession::table() const { return merge_lines; }

const FamilyFacts ZMergeSession::facts = {
    .topic = "Z-buffer",
    .speaks_to = [](const algo::Scene&, const algo::AlgorithmInfo&) { return false; },
    .random_scene = &no_random_scene,
    .measure = &analysis::measure_zbuffer,
};

}  // namespace hsr::viz
