#include "state/raycast_session.h"

#include <array>

#include "core/overloaded.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The lecture's RayCasting; with a grid, the primitives of a ray are those of the cells it walks.
constexpr std::array<std::string_view, 10> cast_lines = {
    "RayCasting(primitiveDB, v):",
    "  for each pixel p:",
    "    minp = MAXINT",
    "    for each cell C the ray (v, p) walks:   /* or: every primitive */",
    "      for each primitive R in C:",
    "        I = intersect_primitive_ray(R, v, p)",
    "        if (|I - v| < minp):",
    "          p -> nearest_primitive = R;  minp = |I - v|",
    "      if (minp is inside C): stop walking",
    "    p sees p -> nearest_primitive",
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

std::span<const std::string_view> RayCastSession::pseudocode() const { return cast_lines; }

std::string RayCastSession::sentence_of(const RayCastEvent& e, const RayView&) { return describe(e); }
std::string RayCastSession::describe_event(const RayCastEvent& e) const { return sentence_of(e, view()); }

int RayCastSession::line_of(const RayCastEvent& event) const {
    return std::visit(overloaded{
                          [](const RayStarted&) { return 2; },
                          [](const CellEntered&) { return 3; },
                          [](const NodeEntered&) { return 3; },
                          [](const PrimitiveTested&) { return 5; },
                          [](const NearerHitFound&) { return 7; },
                          [](const RayFinished&) { return 9; },
                          [](const CastFinished&) { return 1; },
                          [](const CastStepBoundReached&) { return 1; },
                      },
                      event);
}

// A Step is a ray; the cells and tests along it are micro-steps.
bool RayCastSession::is_major(const RayCastEvent& e) const {
    return std::holds_alternative<RayFinished>(e) || std::holds_alternative<CastFinished>(e) ||
           std::holds_alternative<CastStepBoundReached>(e);
}

const FamilyFacts RayCastSession::facts = {
    .speaks_to = [](const algo::Scene& s, const algo::AlgorithmInfo&) {  // the reference every image is measured against
        return !s.expect.image.empty() || expects_from_renderer(s, "raycast");
    },
    .random_scene = &random_triangle_scene,
    .measure = &analysis::measure_hidden_surfaces,
};

}  // namespace hsr::viz
