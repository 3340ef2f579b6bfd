// SPDX-License-Identifier: MIT
#include "clipping/clip_events.h"

#include <cstdio>

#include "core/overloaded.h"

namespace hsr::algo {
namespace {

std::string num(double v) { return format_number(v); }

std::string endpoint(Endpoint e) { return e == Endpoint::p1 ? "p1" : "p2"; }

std::string inequality(ClipPlane p, ClipSpace s) { return std::string(plane_inequality(p, s)); }

}  // namespace

std::string format_point(const Vec4& p, ClipSpace s) {
    std::string out = "(" + num(p.x) + ", " + num(p.y) + ", " + num(p.z);
    if (s == ClipSpace::homogeneous) out += ", " + num(p.w);
    return out + ")";
}

std::string_view to_string(ClipOutcome o) {
    switch (o) {
        case ClipOutcome::inside: return "inside";
        case ClipOutcome::clipped: return "clipped";
        case ClipOutcome::rejected: return "rejected";
    }
    return "?";
}

std::string_view to_string(EdgeCase c) {
    switch (c) {
        case EdgeCase::in_in: return "in→in";
        case EdgeCase::in_out: return "in→out";
        case EdgeCase::out_out: return "out→out";
        case EdgeCase::out_in: return "out→in";
    }
    return "?";
}

std::string_view to_string(BoundaryCase c) {
    switch (c) {
        case BoundaryCase::parallel_inside: return "parallel, inside";
        case BoundaryCase::parallel_outside: return "parallel, outside";
        case BoundaryCase::entering: return "entering";
        case BoundaryCase::leaving: return "leaving";
    }
    return "?";
}

std::string_view to_string(Bound b) {
    switch (b) {
        case Bound::rounds: return "clipping rounds";
        case Bound::vertices: return "polygon vertices";
    }
    return "?";
}

std::string describe(const ClipEvent& event, ClipSpace s) {
    return std::visit(
        overloaded{
            [&](const PointClassified& e) {
                return "point " + std::to_string(e.id) + " at " + format_point(e.p, s) + ": outcode " +
                       to_string(e.code) + (e.code.inside() ? ", inside: kept" : ", outside: clipped away");
            },
            [&](const SegmentStarted& e) {
                return "segment " + std::to_string(e.id) + " from p1 = " + format_point(e.p1, s) +
                       " to p2 = " + format_point(e.p2, s);
            },
            [&](const OutcodeComputed& e) {
                return endpoint(e.endpoint) + " = " + format_point(e.p, s) + " has outcode " + to_string(e.code) +
                       (e.round > 1 ? " (round " + std::to_string(e.round) + ")" : "");
            },
            [&](const CodesCompared& e) {
                const Outcode o = e.c1 | e.c2, a = e.c1 & e.c2;
                return "p1 outcode " + to_string(e.c1) + ", p2 outcode " + to_string(e.c2) + ": OR = " +
                       to_string(o) + (o.inside() ? ", trivially accepted" : ", not trivially accepted") +
                       "; AND = " + to_string(a) + (a.inside() ? ", not trivially rejected" : ", trivially rejected");
            },
            [&](const TriviallyAccepted& e) {
                return "c1 | c2 = " + to_string(e.c1 | e.c2) + ": both endpoints inside, the segment is accepted";
            },
            [&](const TriviallyRejected& e) {
                return "c1 & c2 = " + to_string(e.c1 & e.c2) +
                       ": both endpoints outside one plane, the segment is rejected";
            },
            [&](const PlaneChosen& e) {
                return "the bits differ at plane " + std::string(plane_name(e.plane)) + " (" +
                       inequality(e.plane, s) + "); " + endpoint(e.outside) + " is outside it";
            },
            [&](const IntersectionComputed& e) {
                return "the segment meets " + inequality(e.plane, s) + " at t = " + num(e.t) + ": i = " +
                       format_point(e.point, s) + " replaces " + endpoint(e.replaces);
            },
            [&](const BoundaryTested& e) {
                std::string out = "plane " + inequality(e.plane, s) + ": p = " + num(e.p) + ", q = " + num(e.q);
                if (e.how == BoundaryCase::entering || e.how == BoundaryCase::leaving)
                    out += ", q/p = " + num(e.q / e.p);
                return out + " (" + std::string(to_string(e.how)) + ")";
            },
            [&](const ParameterUpdated& e) {
                return std::string(e.which == Parameter::t_enter ? "t_enter" : "t_leave") + " " + num(e.before) +
                       " → " + num(e.after);
            },
            [&](const SegmentEmptied& e) {
                if (e.t_enter <= e.t_leave)
                    return "the segment is parallel to plane " + inequality(e.plane, s) +
                           " and outside it: rejected";
                return "at plane " + inequality(e.plane, s) + ": t_enter = " + num(e.t_enter) + " > t_leave = " +
                       num(e.t_leave) + ", nothing of the segment is inside: rejected";
            },
            [&](const SegmentFinished& e) {
                std::string out = "segment " + std::to_string(e.id) + " " + std::string(to_string(e.outcome));
                if (e.outcome != ClipOutcome::rejected)
                    out += ": visible from " + format_point(e.a, s) + " to " + format_point(e.b, s);
                return out;
            },
            [&](const PolygonStarted& e) {
                return "polygon " + std::to_string(e.id) + " with " + std::to_string(e.vertices) +
                       " vertices enters the pipeline";
            },
            [&](const StageStarted& e) {
                return "stage " + std::string(plane_name(e.plane)) + " (" + inequality(e.plane, s) + ") takes " +
                       std::to_string(e.input_vertices) + " vertices";
            },
            [&](const EdgeClassified& e) {
                std::string out = "edge v" + std::to_string(e.from) + "→v" +
                                  std::to_string(e.closes ? 0 : e.from + 1) + " is " +
                                  std::string(to_string(e.edge_case)) + " (" + num(e.bc_from) + ", " +
                                  num(e.bc_to) + ")";
                switch (e.edge_case) {
                    case EdgeCase::in_in: return out + ": emits the end vertex";
                    case EdgeCase::in_out: return out + ": emits i = " + format_point(e.intersection, s);
                    case EdgeCase::out_out: return out + ": emits nothing";
                    case EdgeCase::out_in:
                        return out + ": emits i = " + format_point(e.intersection, s) + " and the end vertex";
                }
                return out;
            },
            [&](const StageFinished& e) {
                return "stage " + std::string(plane_name(e.plane)) + " passes on " +
                       std::to_string(e.output_vertices) + " vertices";
            },
            [&](const PolygonFinished& e) {
                return "polygon " + std::to_string(e.id) + " " + std::string(to_string(e.outcome)) + " with " +
                       std::to_string(e.vertices) + " vertices";
            },
            [&](const StepBoundReached& e) {
                return "stopped: the bound of " + std::to_string(e.limit) + " " + std::string(to_string(e.bound)) +
                       " was reached";
            },
        },
        event);
}

}  // namespace hsr::algo
