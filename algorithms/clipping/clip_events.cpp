// SPDX-License-Identifier: MIT
#include "clipping/clip_events.h"

#include <cstdio>

#include "core/overloaded.h"
#include "core/phrase.h"

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

namespace {
// What the clippers say, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying inside{"clipping.inside", "inside"};
constexpr Saying clipped{"clipping.clipped", "clipped"};
constexpr Saying rejected{"clipping.rejected", "rejected"};
constexpr Saying parallel_inside{"clipping.parallel_inside", "parallel, inside"};
constexpr Saying parallel_outside{"clipping.parallel_outside", "parallel, outside"};
constexpr Saying entering{"clipping.entering", "entering"};
constexpr Saying leaving{"clipping.leaving", "leaving"};
constexpr Saying rounds{"clipping.rounds", "clipping rounds"};
constexpr Saying polygon_vertices{"clipping.polygon_vertices", "polygon vertices"};
constexpr Saying trivially_accepted{"clipping.trivially_accepted", "trivially accepted"};
constexpr Saying not_trivially_accepted{"clipping.not_trivially_accepted", "not trivially accepted"};
constexpr Saying trivially_rejected{"clipping.trivially_rejected", "trivially rejected"};
constexpr Saying not_trivially_rejected{"clipping.not_trivially_rejected", "not trivially rejected"};
constexpr Saying point_kept{"clipping.point_kept", "point {id} at {p}: outcode {code}, inside: kept"};
constexpr Saying point_clipped{"clipping.point_clipped", "point {id} at {p}: outcode {code}, outside: clipped away"};
constexpr Saying segment_started{"clipping.segment_started", "segment {id} from p1 = {p1} to p2 = {p2}"};
constexpr Saying outcode{"clipping.outcode", "{endpoint} = {p} has outcode {code}"};
constexpr Saying outcode_round{"clipping.outcode_round", "{endpoint} = {p} has outcode {code} (round {round})"};
constexpr Saying codes_compared{"clipping.codes_compared", "p1 outcode {c1}, p2 outcode {c2}: OR = {or}, {accepted}; AND = {and}, {rejected}"};
constexpr Saying accepted{"clipping.accepted", "c1 | c2 = {or}: both endpoints inside, the segment is accepted"};
constexpr Saying rejected_by_and{"clipping.rejected_by_and", "c1 & c2 = {and}: both endpoints outside one plane, the segment is rejected"};
constexpr Saying plane_chosen{"clipping.plane_chosen", "the bits differ at plane {plane} ({inequality}); {endpoint} is outside it"};
constexpr Saying intersection{"clipping.intersection", "the segment meets {inequality} at t = {t}: i = {i} replaces {endpoint}"};
constexpr Saying boundary{"clipping.boundary", "plane {inequality}: p = {p}, q = {q} ({how})"};
constexpr Saying boundary_ratio{"clipping.boundary_ratio", "plane {inequality}: p = {p}, q = {q}, q/p = {ratio} ({how})"};
constexpr Saying parameter{"clipping.parameter", "{which} {before} → {after}"};
constexpr Saying parallel_outside_rejected{"clipping.parallel_outside_rejected",
                                           "the segment is parallel to plane {inequality} and outside it: rejected"};
constexpr Saying emptied{"clipping.emptied",
                         "at plane {inequality}: t_enter = {t_enter} > t_leave = {t_leave}, nothing of the segment is inside: rejected"};
constexpr Saying segment_rejected{"clipping.segment_rejected", "segment {id} {outcome}"};
constexpr Saying segment_visible{"clipping.segment_visible", "segment {id} {outcome}: visible from {a} to {b}"};
constexpr Saying polygon_started{"clipping.polygon_started", "polygon {id} with {vertices} {vertices?vertex|vertices} enters the pipeline"};
constexpr Saying stage_started{"clipping.stage_started", "stage {plane} ({inequality}) takes {vertices} {vertices?vertex|vertices}"};
constexpr Saying edge_in_in{"clipping.edge_in_in", "edge v{from}→v{to} is {case} ({bc_from}, {bc_to}): emits the end vertex"};
constexpr Saying edge_in_out{"clipping.edge_in_out", "edge v{from}→v{to} is {case} ({bc_from}, {bc_to}): emits i = {i}"};
constexpr Saying edge_out_out{"clipping.edge_out_out", "edge v{from}→v{to} is {case} ({bc_from}, {bc_to}): emits nothing"};
constexpr Saying edge_out_in{"clipping.edge_out_in", "edge v{from}→v{to} is {case} ({bc_from}, {bc_to}): emits i = {i} and the end vertex"};
constexpr Saying stage_finished{"clipping.stage_finished", "stage {plane} passes on {vertices} {vertices?vertex|vertices}"};
constexpr Saying polygon_finished{"clipping.polygon_finished", "polygon {id} {outcome} with {vertices} {vertices?vertex|vertices}"};
constexpr Saying bound_reached{"clipping.bound_reached", "stopped: the bound of {limit} {bound} was reached"};
constexpr Saying all[] = {inside, clipped, rejected, parallel_inside, parallel_outside, entering, leaving, rounds, polygon_vertices,
                          trivially_accepted, not_trivially_accepted, trivially_rejected, not_trivially_rejected, point_kept,
                          point_clipped, segment_started, outcode, outcode_round, codes_compared, accepted, rejected_by_and,
                          plane_chosen, intersection, boundary, boundary_ratio, parameter, parallel_outside_rejected, emptied,
                          segment_rejected, segment_visible, polygon_started, stage_started, edge_in_in, edge_in_out,
                          edge_out_out, edge_out_in, stage_finished, polygon_finished, bound_reached};
}  // namespace say
}  // namespace

const Saying& term(ClipOutcome o) {
    switch (o) {
        case ClipOutcome::inside: return say::inside;
        case ClipOutcome::clipped: return say::clipped;
        case ClipOutcome::rejected: return say::rejected;
    }
    return say::inside;
}

const Saying& term(BoundaryCase c) {
    switch (c) {
        case BoundaryCase::parallel_inside: return say::parallel_inside;
        case BoundaryCase::parallel_outside: return say::parallel_outside;
        case BoundaryCase::entering: return say::entering;
        case BoundaryCase::leaving: return say::leaving;
    }
    return say::entering;
}

const Saying& term(Bound b) { return b == Bound::rounds ? say::rounds : say::polygon_vertices; }

std::string_view to_string(ClipOutcome o) { return term(o).english; }
std::string_view to_string(BoundaryCase c) { return term(c).english; }
std::string_view to_string(Bound b) { return term(b).english; }

std::string_view to_string(EdgeCase c) {
    switch (c) {
        case EdgeCase::in_in: return "in→in";
        case EdgeCase::in_out: return "in→out";
        case EdgeCase::out_out: return "out→out";
        case EdgeCase::out_in: return "out→in";
    }
    return "?";
}

std::span<const Saying> clipping_sayings() { return say::all; }

Phrase phrase(const ClipEvent& event, ClipSpace s) {
    const auto point = [s](const Vec4& p) { return format_point(p, s); };
    const auto plane = [s](ClipPlane p) { return inequality(p, s); };
    const auto id = [](auto v) { return std::to_string(v); };
    return std::visit(
        overloaded{
            [&](const PointClassified& e) {
                return Phrase(e.code.inside() ? say::point_kept : say::point_clipped,
                              {{"id", id(e.id)}, {"p", point(e.p)}, {"code", to_string(e.code)}});
            },
            [&](const SegmentStarted& e) { return Phrase(say::segment_started, {{"id", id(e.id)}, {"p1", point(e.p1)}, {"p2", point(e.p2)}}); },
            [&](const OutcodeComputed& e) {
                return Phrase(e.round > 1 ? say::outcode_round : say::outcode,
                              {{"endpoint", endpoint(e.endpoint)}, {"p", point(e.p)}, {"code", to_string(e.code)}, {"round", id(e.round)}});
            },
            [&](const CodesCompared& e) {
                const Outcode o = e.c1 | e.c2, a = e.c1 & e.c2;
                return Phrase(say::codes_compared,
                              {{"c1", to_string(e.c1)}, {"c2", to_string(e.c2)}, {"or", to_string(o)}, {"and", to_string(a)}},
                              Terms{{"accepted", o.inside() ? &say::trivially_accepted : &say::not_trivially_accepted},
                                    {"rejected", a.inside() ? &say::not_trivially_rejected : &say::trivially_rejected}});
            },
            [&](const TriviallyAccepted& e) { return Phrase(say::accepted, {{"or", to_string(e.c1 | e.c2)}}); },
            [&](const TriviallyRejected& e) { return Phrase(say::rejected_by_and, {{"and", to_string(e.c1 & e.c2)}}); },
            [&](const PlaneChosen& e) {
                return Phrase(say::plane_chosen,
                              {{"plane", std::string(plane_name(e.plane))}, {"inequality", plane(e.plane)}, {"endpoint", endpoint(e.outside)}});
            },
            [&](const IntersectionComputed& e) {
                return Phrase(say::intersection,
                              {{"inequality", plane(e.plane)}, {"t", num(e.t)}, {"i", point(e.point)}, {"endpoint", endpoint(e.replaces)}});
            },
            [&](const BoundaryTested& e) {
                const bool ratio = e.how == BoundaryCase::entering || e.how == BoundaryCase::leaving;
                return Phrase(ratio ? say::boundary_ratio : say::boundary,
                              {{"inequality", plane(e.plane)}, {"p", num(e.p)}, {"q", num(e.q)}, {"ratio", ratio ? num(e.q / e.p) : ""}},
                              Terms{{"how", &term(e.how)}});
            },
            [&](const ParameterUpdated& e) {
                return Phrase(say::parameter,
                              {{"which", e.which == Parameter::t_enter ? "t_enter" : "t_leave"}, {"before", num(e.before)}, {"after", num(e.after)}});
            },
            [&](const SegmentEmptied& e) {
                if (e.t_enter <= e.t_leave) return Phrase(say::parallel_outside_rejected, {{"inequality", plane(e.plane)}});
                return Phrase(say::emptied, {{"inequality", plane(e.plane)}, {"t_enter", num(e.t_enter)}, {"t_leave", num(e.t_leave)}});
            },
            [&](const SegmentFinished& e) {
                if (e.outcome == ClipOutcome::rejected) return Phrase(say::segment_rejected, {{"id", id(e.id)}}, Terms{{"outcome", &term(e.outcome)}});
                return Phrase(say::segment_visible, {{"id", id(e.id)}, {"a", point(e.a)}, {"b", point(e.b)}}, Terms{{"outcome", &term(e.outcome)}});
            },
            [&](const PolygonStarted& e) { return Phrase(say::polygon_started, {{"id", id(e.id)}, {"vertices", id(e.vertices)}}); },
            [&](const StageStarted& e) {
                return Phrase(say::stage_started,
                              {{"plane", std::string(plane_name(e.plane))}, {"inequality", plane(e.plane)}, {"vertices", id(e.input_vertices)}});
            },
            [&](const EdgeClassified& e) {
                const Saying& saying = e.edge_case == EdgeCase::in_in    ? say::edge_in_in
                                       : e.edge_case == EdgeCase::in_out ? say::edge_in_out
                                       : e.edge_case == EdgeCase::out_out ? say::edge_out_out
                                                                          : say::edge_out_in;
                return Phrase(saying, {{"from", id(e.from)},
                                       {"to", id(e.closes ? 0 : e.from + 1)},
                                       {"case", std::string(to_string(e.edge_case))},
                                       {"bc_from", num(e.bc_from)},
                                       {"bc_to", num(e.bc_to)},
                                       {"i", point(e.intersection)}});
            },
            [&](const StageFinished& e) {
                return Phrase(say::stage_finished, {{"plane", std::string(plane_name(e.plane))}, {"vertices", id(e.output_vertices)}});
            },
            [&](const PolygonFinished& e) {
                return Phrase(say::polygon_finished, {{"id", id(e.id)}, {"vertices", id(e.vertices)}}, Terms{{"outcome", &term(e.outcome)}});
            },
            [&](const StepBoundReached& e) { return Phrase(say::bound_reached, {{"limit", id(e.limit)}}, Terms{{"bound", &term(e.bound)}}); },
        },
        event);
}

std::string describe(const ClipEvent& event, ClipSpace s) { return phrase(event, s).english(); }

}  // namespace hsr::algo
