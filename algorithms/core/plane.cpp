// SPDX-License-Identifier: MIT
#include "core/plane.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace hsr::algo {

double Plane::distance(const Vec3& p) const { return glm::dot(n, p) + d; }

Side classify(const Plane& plane, const Vec3& p, Tolerance tol) {
    const double s = plane.distance(p);
    return s > tol.epsilon ? Side::front : s < -tol.epsilon ? Side::back : Side::on;
}

namespace {

double largest_coordinate(std::span<const Vec3> points) {
    double m = 0;
    for (const Vec3& p : points) m = std::max({m, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    return m;
}

// The longest side of the points' bounding box: 0 for one point
double size_of(std::span<const Vec3> points) {
    if (points.empty()) return 0;
    Vec3 lo = points[0], hi = points[0];
    for (const Vec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
}

}  // namespace

Tolerance Tolerance::for_points(std::span<const Vec3> a, std::span<const Vec3> b) {
    return for_extent(std::max(largest_coordinate(a), largest_coordinate(b)));
}


Tolerance Tolerance::for_pair(std::span<const Vec3> planar, std::span<const Vec3> tested) {
    // 32 ulps of the largest number in the sum n · x + d: Newell's normal, d and the dot product each round a few times
    constexpr double rounding = 32 * std::numeric_limits<double>::epsilon();
    const double on_plane = relative * std::min(size_of(planar), size_of(tested));
    const double epsilon = on_plane + rounding * (largest_coordinate(planar) + largest_coordinate(tested));
    return {std::isfinite(epsilon) ? epsilon : std::numeric_limits<double>::max()};
}

PolygonSide classify(const Plane& plane, std::span<const Vec3> polygon, Tolerance tol) {
    bool front = false, back = false;
    for (const Vec3& v : polygon) {
        const Side s = classify(plane, v, tol);
        front = front || s == Side::front;
        back = back || s == Side::back;
    }
    return front && back ? PolygonSide::spanning : front ? PolygonSide::front : back ? PolygonSide::back
                                                                                    : PolygonSide::coplanar;
}

SplitParts split(const Plane& plane, std::span<const Vec3> polygon, Tolerance tol) {
    SplitParts parts;
    const std::size_t n = polygon.size();
    const bool open = n == 2;  // a 2D segment: one edge, not a closed loop
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& a = polygon[i];
        const Side sa = classify(plane, a, tol);
        if (sa != Side::back) parts.front.push_back(a);
        if (sa != Side::front) parts.back.push_back(a);
        if (open && i + 1 == n) break;
        const Vec3& b = polygon[(i + 1) % n];
        const Side sb = classify(plane, b, tol);
        if ((sa == Side::front && sb == Side::back) || (sa == Side::back && sb == Side::front)) {
            // the crossing, computed from the front end so that both neighbours of a shared edge agree
            const Vec3& f = sa == Side::front ? a : b;
            const Vec3& k = sa == Side::front ? b : a;
            const double df = plane.distance(f), dk = plane.distance(k);
            const Vec3 x = f + (k - f) * (df / (df - dk));
            parts.front.push_back(x);
            parts.back.push_back(x);
        }
    }
    return parts;
}

namespace {

// A power of two that brings the polygon's largest coordinate near 1. Newell's products and the normal's length
// square the coordinates: a triangle 1e-160 across gave a normal of 1e-320 (a denormal) whose length underflowed to
// 0, refused as "no area" by the BSP alone. Scaling by a power of two is exact, so the unit normal of every polygon
// within 2^±400 is bit for bit what it was; only those beyond are scaled.
double unit_scale(std::span<const Vec3> polygon) {
    const double largest = largest_coordinate(polygon);
    if (!(largest > 0) || !std::isfinite(largest)) return 1;
    const int e = std::ilogb(largest);
    return e < -400 || e > 400 ? std::ldexp(1.0, -e) : 1.0;
}

}  // namespace

bool plane_of(std::span<const Vec3> polygon, Plane& out) {
    const double k = unit_scale(polygon);
    if (polygon.size() == 2) {
        const Vec3 dir = (polygon[1] - polygon[0]) * k;
        const Vec3 normal(-dir.y, dir.x, 0);  // left of the direction, in the plane z = 0
        const double len = glm::length(normal);
        if (!(len > 0)) return false;
        out.n = normal / len;
        out.d = -glm::dot(out.n, polygon[0]);
        return true;
    }
    Vec3 normal(0), centre(0);
    for (std::size_t i = 0; i < polygon.size(); ++i) {  // Newell's method
        const Vec3 a = polygon[i] * k;
        const Vec3 b = polygon[(i + 1) % polygon.size()] * k;
        normal += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
        centre += polygon[i];
    }
    const double len = glm::length(normal);
    if (polygon.size() < 3 || !(len > 0)) return false;
    out.n = normal / len;
    out.d = -glm::dot(out.n, centre / double(polygon.size()));
    return true;
}

double measure(std::span<const Vec3> polygon) {
    if (polygon.size() == 2) return glm::length(polygon[1] - polygon[0]);
    Vec3 twice(0);
    for (std::size_t i = 0; i < polygon.size(); ++i)
        twice += glm::cross(polygon[i], polygon[(i + 1) % polygon.size()]);
    return 0.5 * glm::length(twice);
}

Vec3 centroid(std::span<const Vec3> polygon) {
    Vec3 c(0);
    for (const Vec3& v : polygon) c += v;
    return polygon.empty() ? c : c / double(polygon.size());
}

std::string_view to_string(Side s) {
    switch (s) {
        case Side::front: return "front";
        case Side::back: return "back";
        case Side::on: return "on";
    }
    return "?";
}

std::string_view to_string(PolygonSide s) {
    switch (s) {
        case PolygonSide::front: return "front";
        case PolygonSide::back: return "back";
        case PolygonSide::coplanar: return "coplanar";
        case PolygonSide::spanning: return "spanning";
    }
    return "?";
}

}  // namespace hsr::algo
