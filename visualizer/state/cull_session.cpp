#include "state/cull_session.h"

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

CullSession::PlayerType make_player(const Lesson& lesson, PlayerOptions options) {
    const auto test = BackfaceTest(lesson.algorithm.variant);
    std::vector<Face> faces = faces_of(lesson.scene);
    CullView initial = initial_view(faces, lesson.scene.camera, test);
    return CullSession::PlayerType(cull_back_faces(std::move(faces), lesson.scene.camera, test), std::move(initial),
                                   options);
}

}  // namespace

CullSession::CullSession(Lesson lesson, PlayerOptions options) : PlayerSession(lesson, make_player(lesson, options)) {}

std::span<const std::string_view> CullSession::pseudocode() const {
    switch (view().test) {
        case BackfaceTest::view_vector: return view_vector_lines;
        case BackfaceTest::plane_equation: return plane_equation_lines;
        case BackfaceTest::screen_winding: return screen_winding_lines;
    }
    return {};
}

std::string CullSession::describe_event(const CullEvent& e) const { return describe(e); }

int CullSession::line_of(const CullEvent& event) const {
    return std::visit(overloaded{
                          [](const FaceTested& e) { return e.facing == Facing::front ? 3 : 5; },
                          [](const CullingFinished&) { return 0; },
                      },
                      event);
}

bool CullSession::is_major(const CullEvent&) const { return true; }  // one event per polygon: every one a Step

}  // namespace hsr::viz
