// SPDX-License-Identifier: MIT
#include "portals/plan_ray.h"

#include <glm/geometric.hpp>

#include "geometry/polygon_2d.h"

namespace hsr::algo {
namespace {


// Where the line p + t·d leaves a convex outline (counter-clockwise: it leaves where it crosses an edge rightwards);
// 1e300 when it crosses none.
double exit_parameter(const std::vector<Vec2>& o, Vec2 p, Vec2 d) {
    double t_exit = 1e300;
    for (std::size_t i = 0; i < o.size(); ++i) {
        const Vec2 a = o[i], e = o[(i + 1) % o.size()] - a;
        const double denom = cross(d, e);
        if (denom > 0) t_exit = std::min(t_exit, cross(a - p, e) / denom);
    }
    return t_exit;
}

}  // namespace

std::vector<std::uint32_t> cells_along_ray(const CellModel& m, std::uint32_t cell, Vec2 p, Vec2 d) {
    std::vector<std::uint32_t> seen{cell};
    for (std::size_t guard = 0; guard < m.cells.size(); ++guard) {  // a straight ray enters each convex cell once
        const double t_exit = exit_parameter(m.cells[cell].outline, p, d);
        if (t_exit >= 1e300) break;
        const Vec2 q = p + t_exit * d;
        // through an opening (strictly inside it), or into a wall
        std::int64_t next = -1;
        for (std::uint32_t k : m.cells[cell].portals) {
            const Portal& portal = m.portals[k];
            const Vec2 along = portal.left - portal.right;
            const double s = glm::dot(q - portal.right, along) / glm::dot(along, along);
            if (std::abs(cross(along, q - portal.right)) <= m.tol.epsilon * glm::length(along) && s > 1e-9 && s < 1 - 1e-9) next = portal.to;
        }
        if (next < 0) break;
        cell = std::uint32_t(next), p = q;
        seen.push_back(cell);
    }
    return seen;
}

std::vector<std::uint32_t> cells_along_ray(const CellModel& m, std::uint32_t cell, Vec3 p, Vec3 d) {
    // The plan ray, with the height along it: world y = p.y + d.y · t where the plan point is plan(p) + t · plan(d)
    const Vec2 p2 = plan_point(p), d2 = plan_point(d);
    std::vector<std::uint32_t> seen{cell};
    double t = 0;  // along the ray, as far as the cell entered last
    for (std::size_t guard = 0; guard < m.cells.size(); ++guard) {
        const double t_exit = exit_parameter(m.cells[cell].outline, p2, d2);
        if (t_exit >= 1e300 || t_exit < t) break;
        const double y = p.y + d.y * t_exit;  // the height where it meets the cell's outline
        if (y <= 0 || y >= m.height) break;   // the floor or the ceiling came first
        const Vec2 q = p2 + t_exit * d2;
        std::int64_t next = -1;
        for (std::uint32_t k : m.cells[cell].portals) {
            const Portal& portal = m.portals[k];
            const Vec2 along = portal.left - portal.right;
            // on the opening's wall, and strictly within its outline there (a ray along its edge meets the wall)
            if (std::abs(cross(along, q - portal.right)) <= m.tol.epsilon * glm::length(along) &&
                in_opening(portal, world_point(q, y), m.tol.epsilon))
                next = portal.to;
        }
        if (next < 0) break;
        cell = std::uint32_t(next), t = t_exit;
        seen.push_back(cell);
    }
    return seen;
}

}  // namespace hsr::algo
