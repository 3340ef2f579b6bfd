// SPDX-License-Identifier: MIT
#include "state/clip_view.h"

#include "core/overloaded.h"

namespace hsr::viz {
namespace {

using namespace hsr::algo;

// Primitives are clipped in order, so the one an event names is almost always the next one.
void activate(ClipView& v, PrimitiveId id) {
    for (std::size_t i = std::size_t(v.active + 1); i < v.primitives.size(); ++i)
        if (v.primitives[i].id == id) {
            v.active = int(i);
            v.primitives.mut(i).status = PrimitiveStatus::clipping;
            break;
        }
    v.plane.reset();
    v.intersections.clear();
    v.t_enter = 0;
    v.t_leave = 1;
    v.round = 0;
    v.stage_input.clear();
    v.stage_output.clear();
    v.edge = -1;
}

PrimitiveState* active(ClipView& v) { return v.active >= 0 ? &v.primitives.mut(std::size_t(v.active)) : nullptr; }

void finish(ClipView& v, ClipOutcome outcome, std::vector<Vec4> visible) {
    if (PrimitiveState* p = active(v)) {
        p->status = PrimitiveStatus::done;
        p->outcome = outcome;
        p->visible = std::move(visible);
    }
    v.plane.reset();
}

}  // namespace

ClipView initial_view(const ClipJob& job, ClipAlgorithm algorithm) {
    ClipView v;
    v.space = job.space;
    v.algorithm = algorithm;
    for (const auto& p : job.points) v.primitives.push_back({.id = p.id, .kind = PrimitiveKind::point, .input = {p.p}});
    if (algorithm != ClipAlgorithm::sutherland_hodgman)
        for (const auto& s : job.segments) v.primitives.push_back({.id = s.id, .kind = PrimitiveKind::segment, .input = {s.p1, s.p2}});
    else
        for (const auto& p : job.polygons) v.primitives.push_back({.id = p.id, .kind = PrimitiveKind::polygon, .input = p.vertices});
    return v;
}

void reduce(ClipView& v, const ClipEvent& event) {
    v.intersecting.reset();  // shown for the step that computes it
    std::visit(
        overloaded{
            [&](const PointClassified& e) {
                activate(v, e.id);
                finish(v, e.code.inside() ? ClipOutcome::inside : ClipOutcome::rejected,
                       e.code.inside() ? std::vector<Vec4>{e.p} : std::vector<Vec4>{});
            },
            [&](const SegmentStarted& e) {
                activate(v, e.id);
                v.p1 = e.p1;
                v.p2 = e.p2;
                v.c1 = v.c2 = Outcode{};
                v.c1_known = v.c2_known = false;
            },
            [&](const OutcodeComputed& e) {
                (e.endpoint == Endpoint::p1 ? v.p1 : v.p2) = e.p;
                (e.endpoint == Endpoint::p1 ? v.c1 : v.c2) = e.code;
                (e.endpoint == Endpoint::p1 ? v.c1_known : v.c2_known) = true;
                if (e.endpoint == Endpoint::p1) v.c2_known = false;  // a new round: p2's code is computed next
                v.round = e.round;
                v.plane.reset();
            },
            [&](const CodesCompared& e) {
                v.c1 = e.c1;
                v.c2 = e.c2;
            },
            [&](const TriviallyAccepted&) {},
            [&](const TriviallyRejected&) {},
            [&](const PlaneChosen& e) { v.plane = e.plane; },
            [&](const IntersectionComputed& e) {
                v.plane = e.plane;
                v.intersecting = ClipView::Intersecting{e.plane, v.p1, v.p2};
                v.intersections.push_back(e.point);
                (e.replaces == Endpoint::p1 ? v.p1 : v.p2) = e.point;
                (e.replaces == Endpoint::p1 ? v.c1_known : v.c2_known) = false;  // mkcode(i) comes next round
            },
            [&](const BoundaryTested& e) { v.plane = e.plane; },
            [&](const ParameterUpdated& e) { (e.which == Parameter::t_enter ? v.t_enter : v.t_leave) = e.after; },
            [&](const SegmentEmptied& e) { v.plane = e.plane; },
            [&](const SegmentFinished& e) {
                finish(v, e.outcome,
                       e.outcome == ClipOutcome::rejected ? std::vector<Vec4>{} : std::vector<Vec4>{e.a, e.b});
            },
            [&](const PolygonStarted& e) {
                activate(v, e.id);
                if (v.active >= 0)
                    for (const Vec4& p : v.primitives[std::size_t(v.active)].input) v.stage_output.push_back(p);
            },
            [&](const StageStarted& e) {
                std::swap(v.stage_input, v.stage_output);
                v.stage_output.clear();
                v.plane = e.plane;
                v.edge = -1;
            },
            [&](const EdgeClassified& e) {
                v.edge = int(e.from);
                const Vec4 end = v.stage_input[(e.from + 1) % v.stage_input.size()];
                if (e.edge_case == EdgeCase::in_out || e.edge_case == EdgeCase::out_in)
                    v.intersecting = ClipView::Intersecting{e.plane, v.stage_input[e.from], end};
                switch (e.edge_case) {
                    case EdgeCase::in_in: v.stage_output.push_back(end); break;
                    case EdgeCase::in_out:
                        v.stage_output.push_back(e.intersection);
                        v.intersections.push_back(e.intersection);
                        break;
                    case EdgeCase::out_in:
                        v.stage_output.push_back(e.intersection);
                        v.stage_output.push_back(end);
                        v.intersections.push_back(e.intersection);
                        break;
                    case EdgeCase::out_out: break;
                }
            },
            [&](const StageFinished&) { v.edge = -1; },
            [&](const PolygonFinished& e) { finish(v, e.outcome, v.stage_output.to_vector()); },
            [&](const StepBoundReached&) {
                v.bound_reached = true;
                if (PrimitiveState* p = active(v)) p->bounded = true;
            },
        },
        event);
}

std::size_t approx_bytes(const ClipView& v) {
    // what a copy costs: the primitives are shared chunk by chunk, the working state is copied
    return sizeof v + v.primitives.copy_bytes() + v.intersections.copy_bytes() + v.stage_input.copy_bytes() +
           v.stage_output.copy_bytes();
}

std::vector<PrimitiveClip> answers(const ClipView& v) {
    std::vector<PrimitiveClip> out;
    for (const auto& p : v.primitives)
        if (p.status == PrimitiveStatus::done) out.push_back({p.id, p.outcome, p.visible, p.bounded});
    return out;
}

}  // namespace hsr::viz
