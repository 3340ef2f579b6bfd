// SPDX-License-Identifier: MIT
#include "raycast/nearest_hit.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/polygon_2d.h"

namespace hsr::algo {
namespace {

// Crossing-number test of p against the polygon projected onto the coordinate plane its normal is closest to.
bool inside(const Vec3& p, std::span<const Vec3> polygon, const Vec3& normal) {
    const Vec3 a = glm::abs(normal);
    const int drop = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    const int u = drop == 0 ? 1 : 0, v = drop == 2 ? 1 : 2;
    bool in = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Vec3 &pi = polygon[i], &pj = polygon[j];
        if ((pi[v] > p[v]) != (pj[v] > p[v]) &&
            p[u] < (pj[u] - pi[u]) * (p[v] - pi[v]) / (pj[v] - pi[v]) + pi[u])
            in = !in;
    }
    return in;
}

}  // namespace

std::optional<double> hit(const Ray& ray, std::span<const Vec3> polygon, const Plane& plane) {
    if (polygon.size() == 2) {  // a 2D segment: solve origin + t·dir = a + s·(b − a) in the plane z = 0
        const Vec3 a = polygon[0], e = polygon[1] - polygon[0], d = ray.direction, w = a - ray.origin;
        const glm::dvec2 d2(d), e2(e), w2(w);
        const double den = cross(d2, e2);
        if (den == 0) return std::nullopt;
        const double t = cross(w2, e2) / den, s = cross(w2, d2) / den;
        if (t > 0 && s >= 0 && s <= 1) return t;
        return std::nullopt;
    }
    const double den = glm::dot(plane.n, ray.direction);
    if (den == 0) return std::nullopt;
    const double t = -plane.distance(ray.origin) / den;
    if (!(t > 0)) return std::nullopt;
    if (!inside(ray.origin + t * ray.direction, polygon, plane.n)) return std::nullopt;
    return t;
}

std::optional<NearestHit> nearest_hit(const Ray& ray, std::span<const std::vector<Vec3>> polygons,
                                      std::span<const Plane> planes) {
    std::optional<NearestHit> best;
    for (std::size_t i = 0; i < polygons.size(); ++i)
        if (auto t = hit(ray, polygons[i], planes[i]); t && (!best || *t < best->t)) best = NearestHit{i, *t};
    return best;
}

}  // namespace hsr::algo
