#include "clipping/sutherland_hodgman.h"

#include <utility>

namespace hsr::algo {
namespace {

// intersect_plane_line, always computed from the inside end towards the outside end, so that an edge shared by two
// polygons (walked in opposite directions) gives bit-identical intersection points.
Vec4 crossing(ClipPlane r, ClipSpace s, const Vec4& in, double bc_in, const Vec4& out, double bc_out) {
    return intersect_plane_line(r, s, in, out, intersection_parameter(bc_in, bc_out));
}

Steps<ClipEvent, PolygonClip> sutherland_hodgman_machine(ClipPolygon polygon, ClipOptions o) {
    const ClipSpace s = o.space;
    co_yield PolygonStarted{polygon.id, std::uint32_t(polygon.vertices.size())};
    if (polygon.vertices.size() > o.max_vertices) {
        co_yield StepBoundReached{Bound::vertices, o.max_vertices};
        co_yield PolygonFinished{polygon.id, ClipOutcome::rejected, 0};
        co_return PolygonClip{ClipOutcome::rejected, {}, true};
    }

    std::vector<Vec4> output = std::move(polygon.vertices), input;
    bool cut = false;
    for (int k = 0; k < plane_count(s) && !output.empty(); ++k) {
        const ClipPlane r = all_planes[k];
        std::swap(input, output);
        output.clear();
        co_yield StageStarted{r, std::uint32_t(input.size())};

        for (std::size_t i = 0; i < input.size(); ++i) {
            const Vec4& v_s = input[i];
            const Vec4& v_e = input[(i + 1) % input.size()];
            const double bs = boundary_value(v_s, r, s), be = boundary_value(v_e, r, s);
            const bool s_in = bs >= 0, e_in = be >= 0;  // inside_test: the sign of the plane equation
            const bool closes = i + 1 == input.size();
            if (s_in && e_in) {
                output.push_back(v_e);
                co_yield EdgeClassified{r, EdgeCase::in_in, closes, std::uint32_t(i), bs, be, {}};
            } else if (s_in) {
                const Vec4 x = crossing(r, s, v_s, bs, v_e, be);
                output.push_back(x);
                co_yield EdgeClassified{r, EdgeCase::in_out, closes, std::uint32_t(i), bs, be, x};
            } else if (e_in) {
                const Vec4 x = crossing(r, s, v_e, be, v_s, bs);
                output.push_back(x);
                output.push_back(v_e);
                co_yield EdgeClassified{r, EdgeCase::out_in, closes, std::uint32_t(i), bs, be, x};
            } else {
                co_yield EdgeClassified{r, EdgeCase::out_out, closes, std::uint32_t(i), bs, be, {}};
            }
            cut = cut || !(s_in && e_in);
        }
        co_yield StageFinished{r, std::uint32_t(output.size())};
        if (output.size() > o.max_vertices) {
            co_yield StepBoundReached{Bound::vertices, o.max_vertices};
            co_yield PolygonFinished{polygon.id, ClipOutcome::clipped, std::uint32_t(output.size())};
            co_return PolygonClip{ClipOutcome::clipped, std::move(output), true};
        }
    }

    const ClipOutcome outcome = output.empty() ? ClipOutcome::rejected : cut ? ClipOutcome::clipped : ClipOutcome::inside;
    co_yield PolygonFinished{polygon.id, outcome, std::uint32_t(output.size())};
    co_return PolygonClip{outcome, std::move(output)};
}

}  // namespace

Steps<ClipEvent, PolygonClip> sutherland_hodgman(ClipPolygon polygon, ClipOptions options) {
    require_finite(polygon);
    return sutherland_hodgman_machine(std::move(polygon), options);
}

}  // namespace hsr::algo
