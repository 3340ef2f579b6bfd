// SPDX-License-Identifier: MIT
#include "analysis/portal_coverage.h"

#include <cmath>
#include <optional>

#include "portals/plan_ray.h"
#include "raycast/nearest_hit.h"
#include "raycast/ray_cast.h"

namespace hsr::analysis {

using algo::Vec2;

Coverage portal_coverage(const algo::CellModel& model, const algo::PortalRenderResult& r, algo::Viewport vp) {
    std::vector<std::uint8_t> seen(model.polygons.size(), 0);
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x) {
            const algo::Ray ray = algo::pixel_ray(model.camera, vp, x, y);
            std::optional<algo::NearestHit> best;
            for (std::size_t k = 0; k < model.polygons.size(); ++k) {
                const auto& p = model.polygons[k];
                if (p.plane.distance(ray.origin) <= 0) continue;  // walls are one-sided: each room's face its room
                if (const auto t = algo::hit(ray, p.vertices, p.plane); t && (!best || *t < best->t)) best = algo::NearestHit{k, *t};
            }
            if (best) seen[best->index] = 1;
        }
    Coverage c;
    for (std::size_t k = 0; k < seen.size(); ++k) {
        c.seen += seen[k];
        c.missed += seen[k] && !r.drawn[k];
        c.drawn_not_seen += !seen[k] && r.drawn[k];
    }
    return c;
}

Vec2 random_point_in(const std::vector<Vec2>& outline, algo::PortableRandom& rng, double margin) {
    Vec2 lo(1e300), hi(-1e300);
    for (const Vec2& v : outline) lo = glm::min(lo, v), hi = glm::max(hi, v);
    for (;;) {
        const double px = rng.uniform(lo.x, hi.x), py = rng.uniform(lo.y, hi.y);  // in this order with every compiler
        if (algo::inside(outline, {px, py}, -margin)) return {px, py};
    }
}

PvsSampling sample_pvs(const algo::CellModel& model, const algo::Pvs& pvs, int rays, std::uint32_t seed) {
    algo::PortableRandom rng(seed);
    std::vector<std::uint8_t> ever(pvs.matrix.size(), 0);
    PvsSampling s;
    for (std::uint32_t c = 0; c < pvs.cells; ++c)
        for (int k = 0; k < rays; ++k) {
            const double a = rng.uniform(0, 2 * M_PI);
            for (std::uint32_t to : algo::cells_along_ray(model, c, random_point_in(model.cells[c].outline, rng), {std::cos(a), std::sin(a)})) {
                s.missed += !pvs.visible(c, to);
                ever[std::size_t(c) * pvs.cells + to] = 1;
            }
        }
    for (std::size_t k = 0; k < ever.size(); ++k) s.slack += pvs.matrix[k] && !ever[k], s.pairs += pvs.matrix[k];
    return s;
}

}  // namespace hsr::analysis
