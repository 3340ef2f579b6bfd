#include "state/backface_session.h"

#include <array>

#include "core/overloaded.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The three tests of the lectures, as one loop each; the line that keeps or culls is highlighted.
constexpr std::array<std::string_view, 6> view_vector_lines = {
    "for each polygon P with outward normal n:",
    "  v = P.vertex[0] - eye        /* the view vector, eye -> P */",
    "  if (dot(v / |v|, n) < 0)     /* P faces the eye */",
    "    keep P;",
    "  else                         /* a back face, or edge-on */",
    "    cull P;",
};
constexpr std::array<std::string_view, 6> plane_equation_lines = {
    "for each polygon P with plane N.x + D = 0:",
    "  s = N.eye + D                /* the eye in P's plane equation */",
    "  if (s > 0)                   /* the eye is in front of P */",
    "    keep P;",
    "  else                         /* behind it, or in its plane */",
    "    cull P;",
};
constexpr std::array<std::string_view, 6> screen_winding_lines = {
    "for each polygon P:",
    "  P' = divide(clip(project(P)))  /* near clipping before the divide */",
    "  if (signed_area(P') > 0)     /* counter-clockwise on screen */",
    "    keep P;",
    "  else                         /* clockwise, or edge-on */",
    "    cull P;",
};

}  // namespace

BackfaceSession::RunType BackfaceSession::machine(const Lesson& lesson) {
    const auto test = machine_of<BackfaceTest>(lesson);
    std::vector<Face> faces = faces_of(lesson.scene);
    BackfaceView initial = initial_view(faces, lesson.scene.camera, test);
    return {cull_back_faces(std::move(faces), lesson.scene.camera, test), std::move(initial)};
}

BackfaceSession::BackfaceSession(Lesson lesson, PlayerOptions options) : PlayerSession(lesson, machine(lesson), options) {}

std::span<const std::string_view> BackfaceSession::pseudocode() const {
    switch (view().test) {
        case BackfaceTest::view_vector: return view_vector_lines;
        case BackfaceTest::plane_equation: return plane_equation_lines;
        case BackfaceTest::screen_winding: return screen_winding_lines;
    }
    return {};
}

std::string BackfaceSession::sentence_of(const CullEvent& e, const BackfaceView&) { return describe(e); }
std::string BackfaceSession::describe_event(const CullEvent& e) const { return sentence_of(e, view()); }

int BackfaceSession::line_of(const CullEvent& event) const {
    return std::visit(overloaded{
                          [](const FaceTested& e) { return e.facing == Facing::front ? 3 : 5; },
                          [](const CullingFinished&) { return 0; },
                      },
                      event);
}

bool BackfaceSession::is_major(const CullEvent&) const { return true; }  // one event per polygon: every one a Step

const FamilyFacts BackfaceSession::facts = {
    .speaks_to = [](const algo::Scene& s, const algo::AlgorithmInfo&) { return !s.expect.cull.empty(); },
    .random_scene = &random_triangle_scene,
    .measure = &analysis::measure_culling,
};

}  // namespace hsr::viz
