// SPDX-License-Identifier: MIT
#include "state/raycast_session.h"

#include "state/strings.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The lecture's RayCasting; with a grid, the primitives of a ray are those of the cells it walks.
const Pseudocode<RayCastEvent> cast_lines = {
    {"RayCasting(primitiveDB, v):", {}},
    {"  for each pixel p:", {step<CastFinished>(), step<CastStepBoundReached>()}},
    {"    minp = MAXINT", {micro<RayStarted>()}},
    {"    for each cell C the ray (v, p) walks:   /* or: every primitive */", {micro<CellEntered>(), micro<NodeEntered>()}},
    {"      for each primitive R in C:", {}},
    {"        I = intersect_primitive_ray(R, v, p)", {micro<PrimitiveTested>()}},
    {"        if (|I - v| < minp):", {}},
    {"          p -> nearest_primitive = R;  minp = |I - v|", {micro<NearerHitFound>()}},
    {"      if (minp is inside C): stop walking", {}},
    {"    p sees p -> nearest_primitive", {step<RayFinished>()}},
};

}  // namespace

RayCastSession::RunType RayCastSession::machine(const Lesson& lesson) {
    const Scene scene = grid_scene(lesson);
    const Viewport grid = lesson.grid;
    const auto a = machine_of<Acceleration>(lesson);
    RayView initial;
    initial.viewport = grid;
    initial.acceleration = a;
    initial.owner.assign(std::size_t(grid.width) * std::size_t(grid.height), -1);
    if (a == Acceleration::grid) initial.grid = std::make_shared<const Grid>(ray_cast_grid(scene));  // the machine's cells
    return {ray_cast(scene, {.viewport = grid, .acceleration = a, .detail = RayDetail::test}), std::move(initial)};
}

RayCastSession::RayCastSession(Lesson lesson, PlayerOptions options)
    : PlayerSession(lesson, machine(lesson), options),
      scene_(grid_scene(lesson)) {}

std::string RayCastSession::sentence_of(const RayCastEvent& e, const RayView&) { return describe(e); }
std::string RayCastSession::describe_event(const RayCastEvent& e) const { return sentence_of(e, view()); }
std::string RayCastSession::speak_event(const RayCastEvent& e) const { return window_strings().say(phrase(e)); }

const Pseudocode<RayCastEvent>& RayCastSession::table() const { return cast_lines; }

const FamilyFacts RayCastSession::facts = {
    .topic = "Ray casting",
    .speaks_to = [](const algo::Scene& s, const algo::AlgorithmInfo&) {  // the reference every image is measured against
        return !s.expect.image.empty() || expects_from_renderer(s, "raycast");
    },
    .random_scene = &random_triangle_scene,
    .measure = &analysis::measure_hidden_surfaces,
};

}  // namespace hsr::viz
