// SPDX-License-Identifier: MIT
#include "state/backface_session.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The three tests of the lectures, as one loop each; the line that keeps or culls is highlighted.
const Pseudocode<CullEvent> view_vector_lines = {
    {"for each polygon P with outward normal n:", {step<CullingFinished>()}},
    {"  v = P.vertex[0] - eye        /* the view vector, eye -> P */", {}},
    {"  if (dot(v / |v|, n) < 0)     /* P faces the eye */", {}},
    {"    keep P;", {step<FaceTested>([](const FaceTested& e) { return e.facing == Facing::front; })}},
    {"  else                         /* a back face, or edge-on */", {}},
    {"    cull P;", {step<FaceTested>()}},
};
const Pseudocode<CullEvent> plane_equation_lines = {
    {"for each polygon P with plane N.x + D = 0:", {step<CullingFinished>()}},
    {"  s = N.eye + D                /* the eye in P's plane equation */", {}},
    {"  if (s > 0)                   /* the eye is in front of P */", {}},
    {"    keep P;", {step<FaceTested>([](const FaceTested& e) { return e.facing == Facing::front; })}},
    {"  else                         /* behind it, or in its plane */", {}},
    {"    cull P;", {step<FaceTested>()}},
};
const Pseudocode<CullEvent> screen_winding_lines = {
    {"for each polygon P:", {step<CullingFinished>()}},
    {"  P' = divide(clip(project(P)))  /* near clipping before the divide */", {}},
    {"  if (signed_area(P') > 0)     /* counter-clockwise on screen */", {}},
    {"    keep P;", {step<FaceTested>([](const FaceTested& e) { return e.facing == Facing::front; })}},
    {"  else                         /* clockwise, or edge-on */", {}},
    {"    cull P;", {step<FaceTested>()}},
};

}  // namespace

BackfaceSession::RunType BackfaceSession::machine(const Lesson& lesson) {
    const auto test = machine_of<BackfaceTest>(lesson);
    std::vector<Face> faces = faces_of(lesson.scene);
    BackfaceView initial = initial_view(faces, lesson.scene.camera, test);
    return {cull_back_faces(std::move(faces), lesson.scene.camera, test), std::move(initial)};
}

BackfaceSession::BackfaceSession(Lesson lesson, PlayerOptions options) : PlayerSession(lesson, machine(lesson), options) {}

std::string BackfaceSession::sentence_of(const CullEvent& e, const BackfaceView&) { return describe(e); }
std::string BackfaceSession::describe_event(const CullEvent& e) const { return sentence_of(e, view()); }
std::string BackfaceSession::speak_event(const CullEvent& e) const { return window_strings().say(phrase(e)); }

// One event per polygon: every one a Step.
const Pseudocode<CullEvent>& BackfaceSession::table() const {
    switch (view().test) {
        case BackfaceTest::view_vector: return view_vector_lines;
        case BackfaceTest::plane_equation: return plane_equation_lines;
        case BackfaceTest::screen_winding: break;
    }
    return screen_winding_lines;
}

const FamilyFacts BackfaceSession::facts = {
    .topic = "Back-face culling",
    .speaks_to = [](const algo::Scene& s, const algo::AlgorithmInfo&) { return !s.expect.cull.empty(); },
    .random_scene = &random_triangle_scene,
    .measure = &analysis::measure_culling,
};

}  // namespace hsr::viz
