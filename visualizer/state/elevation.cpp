// SPDX-License-Identifier: MIT
#include "state/elevation.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace hsr::viz {
namespace {

// The heights of a vertical opening where the plan point `at` lies on its wall: its outline cut by the vertical
// line there. The plan's (x, y) is the world's (x, −z); heights are world y.
std::optional<std::pair<double, double>> heights_at(const algo::Portal& p, glm::dvec2 at, double eps) {
    const glm::dvec2 along = p.right - p.left;
    const double length2 = glm::dot(along, along);
    if (length2 <= 0) return std::nullopt;
    const auto u = [&](const algo::Vec3& w) { return glm::dot(glm::dvec2(w.x, -w.z) - p.left, along) / length2; };
    const double u0 = glm::dot(at - p.left, along) / length2;
    double lo = 1e300, hi = -1e300;
    const auto& o = p.opening;
    for (std::size_t i = 0; i < o.size(); ++i) {
        const algo::Vec3 &a = o[i], &b = o[(i + 1) % o.size()];
        const double ua = u(a), ub = u(b);
        if (std::abs(ua - u0) <= eps) lo = std::min(lo, a.y), hi = std::max(hi, a.y);
        if ((ua - u0) * (ub - u0) < 0) {
            const double h = a.y + (b.y - a.y) * (u0 - ua) / (ub - ua);
            lo = std::min(lo, h), hi = std::max(hi, h);
        }
    }
    if (lo > hi) return std::nullopt;
    return std::pair{lo, hi};
}

bool through(const glm::dvec2& line, const ElevationGap& g, double eps) {
    const double h = line.x + line.y * g.s;
    return h >= g.bottom - eps && h <= g.top + eps;
}

// The steepest and shallowest lines through gaps [0, n): each such extreme line passes through ends of two gaps at
// different distances (the lines through vertical gaps form a convex set whose corners are such lines).
std::vector<glm::dvec2> extreme_lines(const std::vector<ElevationGap>& gaps, std::size_t n, double eps) {
    std::vector<glm::dvec2> ok;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            if (std::abs(gaps[j].s - gaps[i].s) <= eps) continue;
            for (const double hi : {gaps[i].bottom, gaps[i].top})
                for (const double hj : {gaps[j].bottom, gaps[j].top}) {
                    const double b = (hj - hi) / (gaps[j].s - gaps[i].s);
                    const glm::dvec2 line(hi - b * gaps[i].s, b);
                    bool all = true;
                    for (std::size_t k = 0; k < n && all; ++k) all = through(line, gaps[k], eps);
                    if (all) ok.push_back(line);
                }
        }
    if (ok.empty()) return ok;
    const auto [shallow, steep] = std::minmax_element(ok.begin(), ok.end(), [](auto& p, auto& q) { return p.y < q.y; });
    return {*shallow, *steep};
}

}  // namespace

std::optional<Elevation> elevation_of(const algo::CellModel& model, const std::vector<std::uint32_t>& run,
                                      glm::dvec2 point, glm::dvec2 direction) {
    if (run.empty() || glm::length(direction) <= 0) return std::nullopt;
    const glm::dvec2 d = glm::normalize(direction);
    const double eps = std::max(model.tol.epsilon, 1e-12);
    Elevation e;
    e.height = model.height;
    for (std::uint32_t k : run) {
        if (k >= model.portals.size()) return std::nullopt;
        const algo::Portal& p = model.portals[k];
        // where the plan line meets the portal's wall: point + t·d = left + u·(right − left)
        const glm::dvec2 w = p.right - p.left;
        const double det = d.x * (-w.y) - d.y * (-w.x);
        if (std::abs(det) <= eps * glm::length(w)) return std::nullopt;  // along the wall: no crossing to draw
        const glm::dvec2 r = p.left - point;
        const double t = (r.x * (-w.y) - r.y * (-w.x)) / det;
        const auto h = heights_at(p, point + t * d, 1e-9);
        if (!h) return std::nullopt;
        e.gaps.push_back({k, t, h->first, h->second});
    }
    const double height_eps = 1e-9 * std::max(1.0, model.height);
    e.reached = std::min<std::size_t>(e.gaps.size(), 1);
    e.extremes.clear();
    for (std::size_t n = 2; n <= e.gaps.size(); ++n) {
        auto lines = extreme_lines(e.gaps, n, height_eps);
        if (lines.empty()) break;
        e.reached = n, e.extremes = std::move(lines);
    }
    if (e.gaps.size() == 1) e.reached = 1;
    return e;
}

}  // namespace hsr::viz
