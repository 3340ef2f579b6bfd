// SPDX-License-Identifier: MIT
#include "state/clip_pseudocode.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// The lecture's CS_Clip_3D ("3D Clipping Algorithms (2)"), after the one line of point clipping. Lines are kept
// under 56 characters so that the panel shows them whole on a 1280-pixel projector.
const Pseudocode<ClipEvent> cohen_sutherland = {
    {"keep_point(p): keep p if mkcode(p) == 000000", {step<PointClassified>()}},
    {"CS_Clip_3D ( vertex p1, p2 )", {step<SegmentStarted>()}},
    {"{", {}},
    {"  int c1, c2;   vertex I;   plane R;", {}},
    {"  c1 = mkcode (p1);    c2 = mkcode (p2);", {micro<OutcodeComputed>()}},
    {"  if ((c1 | c2) == 0) /* p1p2 is inside */", {step<CodesCompared>(), step<TriviallyAccepted>()}},
    {"  else if ((c1 & c2) != 0) /* p1p2 is outside */", {step<TriviallyRejected>()}},
    {"  else { R = /* frustum plane with (c1 bit != c2 bit) */", {micro<PlaneChosen>()}},
    {"    i = intersect_plane_line (R, (p1,p2));", {step<IntersectionComputed>()}},
    {"    if outside (R, p1) CS_Clip_3D(i, p2);", {step<StepBoundReached>()}},
    {"    else CS_Clip_3D(p1, i); }", {}},
    {"}", {step<SegmentFinished>()}},
};

// Liang–Barsky with the lecture's p_i, q_i ("3D Clipping Algorithms (5)"); "the rest remains as in 2D".
const Pseudocode<ClipEvent> liang_barsky = {
    {"keep_point(p): keep p if mkcode(p) == 000000", {step<PointClassified>()}},
    {"LB_Clip_3D ( vertex p1, p2 )", {}},
    {"{ t_enter = 0;  t_leave = 1;", {step<SegmentStarted>()}},
    {"  for i = 1 .. 6:           /* t p_i <= q_i */", {step<StepBoundReached>()}},
    {"    if (p_i == 0)           /* parallel */",
     {step<BoundaryTested>([](const BoundaryTested& e) { return e.how == BoundaryCase::parallel_inside; })}},
    {"      { if (q_i < 0) reject; }",
     {step<BoundaryTested>([](const BoundaryTested& e) { return e.how == BoundaryCase::parallel_outside; }),
      step<SegmentEmptied>([](const SegmentEmptied& e) { return !(e.t_enter > e.t_leave); })}},
    {"    else if (p_i < 0)       /* entering */",
     {step<BoundaryTested>([](const BoundaryTested& e) { return e.how == BoundaryCase::entering; })}},
    {"      t_enter = max(t_enter, q_i / p_i);",
     {micro<ParameterUpdated>([](const ParameterUpdated& e) { return e.which == Parameter::t_enter; })}},
    {"    else                    /* leaving */",
     {step<BoundaryTested>([](const BoundaryTested& e) { return e.how == BoundaryCase::leaving; })}},
    {"      t_leave = min(t_leave, q_i / p_i);", {micro<ParameterUpdated>()}},
    {"    if (t_enter > t_leave) reject;",
     {step<SegmentEmptied>(), step<SegmentFinished>([](const SegmentFinished& e) { return e.outcome == ClipOutcome::rejected; })}},
    {"  return ( l(t_enter), l(t_leave) );", {step<SegmentFinished>()}},
    {"}", {}},
    {"/* p_1 = -dx - dw,  q_1 = x1 + w1,  ...  */", {}},
    {"/* clip space adds i = 7:  w >= eps */", {}},
};

// Sutherland–Hodgman as 6 pipelined stages ("3D Clipping Algorithms (6)").
const Pseudocode<ClipEvent> sutherland_hodgman = {
    {"keep_point(p): keep p if mkcode(p) == 000000", {step<PointClassified>()}},
    {"SH_Clip_3D ( polygon P )", {step<PolygonStarted>()}},
    {"{ for each plane R of the view volume: /* 6 stages */", {step<StepBoundReached>()}},
    {"    out = empty;", {micro<StageStarted>()}},
    {"    for each edge (s, e) of P:", {}},
    {"      if inside(R, e)", {}},
    {"        if inside(R, s) emit(e);         /* in -> in */",
     {step<EdgeClassified>([](const EdgeClassified& e) { return e.edge_case == EdgeCase::in_in; })}},
    {"        else { emit(intersect_plane_line(R,s,e));",
     {step<EdgeClassified>([](const EdgeClassified& e) { return e.edge_case == EdgeCase::out_in; })}},
    {"               emit(e); }                /* out -> in */", {}},
    {"      else if inside(R, s)               /* in -> out */",
     {step<EdgeClassified>([](const EdgeClassified& e) { return e.edge_case == EdgeCase::in_out; })}},
    {"        emit(intersect_plane_line(R,s,e));", {}},
    {"      /* else out -> out: emit nothing */", {step<EdgeClassified>()}},
    {"    P = out;", {step<StageFinished>()}},
    {"  return P;", {step<PolygonFinished>()}},
    {"}", {}},
    {"/* clip space adds a 7th stage:  w >= eps */", {}},
};

}  // namespace

const Pseudocode<ClipEvent>& pseudocode_table(ClipAlgorithm a) {
    switch (a) {
        case ClipAlgorithm::cohen_sutherland: return cohen_sutherland;
        case ClipAlgorithm::liang_barsky: return liang_barsky;
        case ClipAlgorithm::sutherland_hodgman: break;
    }
    return sutherland_hodgman;
}

}  // namespace hsr::viz
