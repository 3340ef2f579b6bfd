// SPDX-License-Identifier: MIT
#include "clipping/sutherland_hodgman.h"

#include <utility>

#include "clipping/carried_boundaries.h"

namespace hsr::algo {
namespace {

using Vertex = CarriedVertex<double>;  // a point and its boundary value for each plane (carried_boundaries.h)

Vertex input_vertex(const Vec4& p, ClipSpace s) {
    Vertex v{p, {}};
    for (std::size_t k = 0; k < v.b.size(); ++k) v.b[k] = boundary_value(p, all_planes[k], s);
    return v;
}

// intersect_plane_line(R, in, out), with t from the carried boundary values, from the inside end towards the outside
// end so that an edge shared by two polygons (walked in opposite directions) gives bit-identical points.
Vertex crossing(ClipPlane r, ClipSpace s, const Vertex& in, const Vertex& out) {
    return cut_edge(int(r), in, out,
                    [&](const Vec4& from, const Vec4& to, double t) { return intersect_plane_line(r, s, from, to, t); });
}

Steps<ClipEvent, PolygonClip> sutherland_hodgman_machine(ClipPolygon polygon, ClipOptions o) {
    const ClipSpace s = o.space;
    co_yield PolygonStarted{polygon.id, std::uint32_t(polygon.vertices.size())};
    if (polygon.vertices.size() > o.max_vertices) {
        co_yield StepBoundReached{Bound::vertices, o.max_vertices};
        co_yield PolygonFinished{polygon.id, ClipOutcome::rejected, 0};
        co_return PolygonClip{ClipOutcome::rejected, {}, true};
    }

    std::vector<Vertex> output, input;
    for (const Vec4& p : polygon.vertices) output.push_back(input_vertex(p, s));
    auto points = [](const std::vector<Vertex>& list) {
        std::vector<Vec4> p;
        p.reserve(list.size());
        for (const Vertex& v : list) p.push_back(v.p);
        return p;
    };
    bool cut = false;
    for (int k = 0; k < plane_count(s) && !output.empty(); ++k) {
        const ClipPlane r = all_planes[k];
        std::swap(input, output);
        output.clear();
        co_yield StageStarted{r, std::uint32_t(input.size())};

        for (std::size_t i = 0; i < input.size(); ++i) {
            const Vertex& v_s = input[i];
            const Vertex& v_e = input[(i + 1) % input.size()];
            const double bs = v_s.b[std::size_t(r)], be = v_e.b[std::size_t(r)];
            const bool s_in = bs >= 0, e_in = be >= 0;  // inside_test: the sign of the plane equation
            const bool closes = i + 1 == input.size();
            if (s_in && e_in) {
                output.push_back(v_e);
                co_yield EdgeClassified{r, EdgeCase::in_in, closes, std::uint32_t(i), bs, be, {}};
            } else if (s_in) {
                const Vertex x = crossing(r, s, v_s, v_e);
                output.push_back(x);
                co_yield EdgeClassified{r, EdgeCase::in_out, closes, std::uint32_t(i), bs, be, x.p};
            } else if (e_in) {
                const Vertex x = crossing(r, s, v_e, v_s);
                output.push_back(x);
                output.push_back(v_e);
                co_yield EdgeClassified{r, EdgeCase::out_in, closes, std::uint32_t(i), bs, be, x.p};
            } else {
                co_yield EdgeClassified{r, EdgeCase::out_out, closes, std::uint32_t(i), bs, be, {}};
            }
            cut = cut || !(s_in && e_in);
        }
        co_yield StageFinished{r, std::uint32_t(output.size())};
        if (output.size() > o.max_vertices) {
            co_yield StepBoundReached{Bound::vertices, o.max_vertices};
            co_yield PolygonFinished{polygon.id, ClipOutcome::clipped, std::uint32_t(output.size())};
            co_return PolygonClip{ClipOutcome::clipped, points(output), true};
        }
    }

    const ClipOutcome outcome = output.empty() ? ClipOutcome::rejected : cut ? ClipOutcome::clipped : ClipOutcome::inside;
    co_yield PolygonFinished{polygon.id, outcome, std::uint32_t(output.size())};
    co_return PolygonClip{outcome, points(output)};
}

}  // namespace

Steps<ClipEvent, PolygonClip> sutherland_hodgman(ClipPolygon polygon, ClipOptions options) {
    require_clippable(polygon);
    return sutherland_hodgman_machine(std::move(polygon), options);
}

}  // namespace hsr::algo
