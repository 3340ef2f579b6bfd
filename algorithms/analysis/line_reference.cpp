// SPDX-License-Identifier: MIT
#include "analysis/line_reference.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace hsr::analysis {

namespace {

enum class Sight { visible, hidden, unsure };

// Does the body hide point p from the eye? The segment p → eye (orthographic: p → p + L·back) inside every plane.
Sight seen_through(const algo::Scene& s, const algo::ConvexBody& body, algo::Vec3 p) {
    const algo::Vec3 to = s.camera.projection == algo::Projection::orthographic
                              ? p + 1000.0 * glm::normalize(s.camera.eye - s.camera.target)
                              : s.camera.eye;
    double enter = 0, leave = 1;
    for (const algo::Plane& plane : body.planes) {
        const double f0 = plane.distance(p), df = glm::dot(plane.n, to - p);
        if (std::abs(df) < 1e-15) {
            if (f0 >= 0) return f0 < 1e-9 ? Sight::unsure : Sight::visible;
            continue;
        }
        const double u = -f0 / df;
        if (df > 0) leave = std::min(leave, u);
        else enter = std::max(enter, u);
    }
    const double length = (leave - enter) * glm::length(to - p);
    if (length > 1e-7) return Sight::hidden;
    if (length < -1e-7) return Sight::visible;
    return Sight::unsure;
}

}  // namespace

LineAgreement against_rays(const algo::Scene& s, const algo::LineDrawing& d, int samples) {
    LineAgreement a;
    for (std::size_t e = 0; e < d.input.edges.size(); ++e) {
        if (d.edges[e].removed) continue;
        const algo::BodyEdge& edge = d.input.edges[e];
        for (int k = 0; k < samples; ++k) {
            const double t = (k + 0.5) / samples;
            const algo::Vec3 p = edge.a + t * (edge.b - edge.a);
            Sight want = Sight::visible;
            for (std::uint32_t b = 0; b < d.input.bodies.size() && want != Sight::hidden; ++b) {
                if (b == edge.body) continue;
                const Sight by = seen_through(s, d.input.bodies[b], p);
                if (by == Sight::hidden) want = Sight::hidden;
                else if (by == Sight::unsure) want = Sight::unsure;
            }
            bool got = false, near_end = false;
            for (const auto& [t0, t1] : d.edges[e].hidden) {
                got |= t >= t0 && t <= t1;
                near_end |= std::abs(t - t0) < 1e-6 || std::abs(t - t1) < 1e-6;
            }
            if (want == Sight::unsure || near_end) {
                ++a.unsure;
                continue;
            }
            ++a.compared;
            a.wrong += got != (want == Sight::hidden);
        }
    }
    return a;
}

}  // namespace hsr::analysis
