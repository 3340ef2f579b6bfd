#include "state/clip_pseudocode.h"

#include <array>

#include "core/overloaded.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The lecture's CS_Clip_3D ("3D Clipping Algorithms (2)"), after the one line of point clipping. Lines are kept
// under 56 characters so that the panel shows them whole on a 1280-pixel projector.
constexpr std::array<std::string_view, 12> cohen_sutherland_lines = {
    "keep_point(p): keep p if mkcode(p) == 000000",
    "CS_Clip_3D ( vertex p1, p2 )",
    "{",
    "  int c1, c2;   vertex I;   plane R;",
    "  c1 = mkcode (p1);    c2 = mkcode (p2);",
    "  if ((c1 | c2) == 0) /* p1p2 is inside */",
    "  else if ((c1 & c2) != 0) /* p1p2 is outside */",
    "  else { R = /* frustum plane with (c1 bit != c2 bit) */",
    "    i = intersect_plane_line (R, (p1,p2));",
    "    if outside (R, p1) CS_Clip_3D(i, p2);",
    "    else CS_Clip_3D(p1, i); }",
    "}",
};

// Liang–Barsky with the lecture's p_i, q_i ("3D Clipping Algorithms (5)"); "the rest remains as in 2D".
constexpr std::array<std::string_view, 15> liang_barsky_lines = {
    "keep_point(p): keep p if mkcode(p) == 000000",
    "LB_Clip_3D ( vertex p1, p2 )",
    "{ t_enter = 0;  t_leave = 1;",
    "  for i = 1 .. 6:           /* t p_i <= q_i */",
    "    if (p_i == 0)           /* parallel */",
    "      { if (q_i < 0) reject; }",
    "    else if (p_i < 0)       /* entering */",
    "      t_enter = max(t_enter, q_i / p_i);",
    "    else                    /* leaving */",
    "      t_leave = min(t_leave, q_i / p_i);",
    "    if (t_enter > t_leave) reject;",
    "  return ( l(t_enter), l(t_leave) );",
    "}",
    "/* p_1 = -dx - dw,  q_1 = x1 + w1,  ...  */",
    "/* clip space adds i = 7:  w >= eps */",
};

// Sutherland–Hodgman as 6 pipelined stages ("3D Clipping Algorithms (6)").
constexpr std::array<std::string_view, 16> sutherland_hodgman_lines = {
    "keep_point(p): keep p if mkcode(p) == 000000",
    "SH_Clip_3D ( polygon P )",
    "{ for each plane R of the view volume: /* 6 stages */",
    "    out = empty;",
    "    for each edge (s, e) of P:",
    "      if inside(R, e)",
    "        if inside(R, s) emit(e);         /* in -> in */",
    "        else { emit(intersect_plane_line(R,s,e));",
    "               emit(e); }                /* out -> in */",
    "      else if inside(R, s)               /* in -> out */",
    "        emit(intersect_plane_line(R,s,e));",
    "      /* else out -> out: emit nothing */",
    "    P = out;",
    "  return P;",
    "}",
    "/* clip space adds a 7th stage:  w >= eps */",
};

int cohen_sutherland_line(const ClipEvent& event) {
    return std::visit(overloaded{
                          [](const PointClassified&) { return 0; },
                          [](const SegmentStarted&) { return 1; },
                          [](const OutcodeComputed&) { return 4; },
                          [](const CodesCompared&) { return 5; },
                          [](const TriviallyAccepted&) { return 5; },
                          [](const TriviallyRejected&) { return 6; },
                          [](const PlaneChosen&) { return 7; },
                          [](const IntersectionComputed&) { return 8; },
                          [](const BoundaryTested&) { return -1; },
                          [](const ParameterUpdated&) { return -1; },
                          [](const SegmentEmptied&) { return -1; },
                          [](const SegmentFinished&) { return 11; },
                          [](const PolygonStarted&) { return -1; },
                          [](const StageStarted&) { return -1; },
                          [](const EdgeClassified&) { return -1; },
                          [](const StageFinished&) { return -1; },
                          [](const PolygonFinished&) { return -1; },
                          [](const StepBoundReached&) { return 9; },
                      },
                      event);
}

int liang_barsky_line(const ClipEvent& event) {
    return std::visit(overloaded{
                          [](const PointClassified&) { return 0; },
                          [](const SegmentStarted&) { return 2; },
                          [](const OutcodeComputed&) { return -1; },
                          [](const CodesCompared&) { return -1; },
                          [](const TriviallyAccepted&) { return -1; },
                          [](const TriviallyRejected&) { return -1; },
                          [](const PlaneChosen&) { return -1; },
                          [](const IntersectionComputed&) { return -1; },
                          [](const BoundaryTested& e) {
                              switch (e.how) {
                                  case BoundaryCase::parallel_inside: return 4;
                                  case BoundaryCase::parallel_outside: return 5;
                                  case BoundaryCase::entering: return 6;
                                  case BoundaryCase::leaving: return 8;
                              }
                              return 3;
                          },
                          [](const ParameterUpdated& e) { return e.which == Parameter::t_enter ? 7 : 9; },
                          [](const SegmentEmptied& e) { return e.t_enter > e.t_leave ? 10 : 5; },
                          [](const SegmentFinished& e) { return e.outcome == ClipOutcome::rejected ? 10 : 11; },
                          [](const PolygonStarted&) { return -1; },
                          [](const StageStarted&) { return -1; },
                          [](const EdgeClassified&) { return -1; },
                          [](const StageFinished&) { return -1; },
                          [](const PolygonFinished&) { return -1; },
                          [](const StepBoundReached&) { return 3; },
                      },
                      event);
}

int sutherland_hodgman_line(const ClipEvent& event) {
    return std::visit(overloaded{
                          [](const PointClassified&) { return 0; },
                          [](const SegmentStarted&) { return -1; },
                          [](const OutcodeComputed&) { return -1; },
                          [](const CodesCompared&) { return -1; },
                          [](const TriviallyAccepted&) { return -1; },
                          [](const TriviallyRejected&) { return -1; },
                          [](const PlaneChosen&) { return -1; },
                          [](const IntersectionComputed&) { return -1; },
                          [](const BoundaryTested&) { return -1; },
                          [](const ParameterUpdated&) { return -1; },
                          [](const SegmentEmptied&) { return -1; },
                          [](const SegmentFinished&) { return -1; },
                          [](const PolygonStarted&) { return 1; },
                          [](const StageStarted&) { return 3; },
                          [](const EdgeClassified& e) {
                              switch (e.edge_case) {
                                  case EdgeCase::in_in: return 6;
                                  case EdgeCase::out_in: return 7;
                                  case EdgeCase::in_out: return 9;
                                  case EdgeCase::out_out: return 11;
                              }
                              return 4;
                          },
                          [](const StageFinished&) { return 12; },
                          [](const PolygonFinished&) { return 13; },
                          [](const StepBoundReached&) { return 2; },
                      },
                      event);
}

}  // namespace

std::span<const std::string_view> pseudocode(ClipAlgorithm a) {
    switch (a) {
        case ClipAlgorithm::cohen_sutherland: return cohen_sutherland_lines;
        case ClipAlgorithm::liang_barsky: return liang_barsky_lines;
        case ClipAlgorithm::sutherland_hodgman: return sutherland_hodgman_lines;
    }
    return {};
}

int pseudocode_line(ClipAlgorithm a, const ClipEvent& e) {
    switch (a) {
        case ClipAlgorithm::cohen_sutherland: return cohen_sutherland_line(e);
        case ClipAlgorithm::liang_barsky: return liang_barsky_line(e);
        case ClipAlgorithm::sutherland_hodgman: return sutherland_hodgman_line(e);
    }
    return -1;
}

bool is_major(const ClipEvent& event) {
    return std::visit(overloaded{
                          [](const PointClassified&) { return true; },
                          [](const SegmentStarted&) { return true; },
                          [](const OutcodeComputed&) { return false; },
                          [](const CodesCompared&) { return true; },
                          [](const TriviallyAccepted&) { return true; },
                          [](const TriviallyRejected&) { return true; },
                          [](const PlaneChosen&) { return false; },
                          [](const IntersectionComputed&) { return true; },
                          [](const BoundaryTested&) { return true; },
                          [](const ParameterUpdated&) { return false; },
                          [](const SegmentEmptied&) { return true; },
                          [](const SegmentFinished&) { return true; },
                          [](const PolygonStarted&) { return true; },
                          [](const StageStarted&) { return false; },
                          [](const EdgeClassified&) { return true; },
                          [](const StageFinished&) { return true; },
                          [](const PolygonFinished&) { return true; },
                          [](const StepBoundReached&) { return true; },
                      },
                      event);
}

}  // namespace hsr::viz
