// SPDX-License-Identifier: MIT
// The oriented bounding box: the principal axes of the object's points, or, for an object with few face directions
// (a box, a prism, a crate), a face's normal as one axis with the smallest rectangle of the points seen along it.
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "culling/bounding_volume.h"
#include "geometry/polygon_2d.h"

namespace hsr::algo {

namespace {

// Eigenvectors of a symmetric 3×3 matrix by cyclic Jacobi rotations (columns of v).
void jacobi(double a[3][3], double v[3][3]) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) v[i][j] = i == j;
    for (int sweep = 0; sweep < 50; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        if (off < 1e-30) return;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (std::abs(a[p][q]) < 1e-300) continue;
                const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
                const double t = (theta >= 0 ? 1 : -1) / (std::abs(theta) + std::sqrt(theta * theta + 1));
                const double c = 1 / std::sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < 3; ++k) {  // a = Jᵀ a J
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq, a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk, a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq, v[k][q] = s * vkp + c * vkq;
                }
            }
    }
}

// The box with these axes (made orthonormal and right-handed from the first two) that holds every point.
Obb box_along(Vec3 first, Vec3 second, std::span<const Vec3> points) {
    Obb box;
    box.axes[0] = glm::normalize(first);
    box.axes[2] = glm::normalize(glm::cross(box.axes[0], second));
    box.axes[1] = glm::cross(box.axes[2], box.axes[0]);
    Vec3 lo(1e300), hi(-1e300);
    for (const Vec3& p : points)
        for (int k = 0; k < 3; ++k) {
            const double t = glm::dot(p, box.axes[std::size_t(k)]);
            lo[k] = std::min(lo[k], t), hi[k] = std::max(hi[k], t);
        }
    box.half = (hi - lo) / 2.0;
    const Vec3 mid = (hi + lo) / 2.0;
    box.centre = box.axes[0] * mid.x + box.axes[1] * mid.y + box.axes[2] * mid.z;
    return box;
}

// Principal components: the eigenvectors of the covariance of the distinct points (a corner shared by six
// triangles counts once, else it pulls the axes towards itself).
Obb principal_box(std::span<const Vec3> distinct) {
    Vec3 mean(0);
    for (const Vec3& p : distinct) mean += p / double(distinct.size());
    double c[3][3] = {};
    for (const Vec3& p : distinct) {
        const Vec3 d = p - mean;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) c[i][j] += d[i] * d[j];
    }
    double v[3][3];
    jacobi(c, v);
    return box_along(Vec3(v[0][0], v[1][0], v[2][0]), Vec3(v[0][1], v[1][1], v[2][1]), distinct);
}

// The box with `normal` as one axis: the smallest rectangle holding the points projected on the plane across it has
// a side on an edge of their convex hull (Freeman and Shapira), so each hull edge is tried.
Obb box_on_face(Vec3 normal, std::span<const Vec3> distinct) {
    const Vec3 u = glm::normalize(std::abs(normal.x) < 0.9 ? glm::cross(normal, Vec3(1, 0, 0)) : glm::cross(normal, Vec3(0, 1, 0)));
    const Vec3 w = glm::cross(normal, u);
    std::vector<glm::dvec2> flat;
    flat.reserve(distinct.size());
    for (const Vec3& p : distinct) flat.emplace_back(glm::dot(p, u), glm::dot(p, w));
    const std::vector<glm::dvec2> hull = convex_hull(std::move(flat));
    Obb best = box_along(u, w, distinct);
    for (std::size_t i = 0; hull.size() >= 3 && i < hull.size(); ++i) {
        const glm::dvec2 e = hull[(i + 1) % hull.size()] - hull[i];
        if (!(glm::length(e) > 0)) continue;
        const Obb b = box_along(u * e.x + w * e.y, normal, distinct);
        if (b.volume() < best.volume()) best = b;
    }
    return best;
}

}  // namespace

std::vector<Vec3> face_normals(std::span<const std::vector<Vec3>> polygons) {
    std::vector<Vec3> out;
    for (const auto& poly : polygons)
        if (Plane plane; poly.size() >= 3 && plane_of(poly, plane)) out.push_back(plane.n);  // Newell's, any winding
    return out;
}

Obb obb_of(std::span<const Vec3> points, std::span<const Vec3> normals) {
    if (points.empty()) return Obb{};
    std::vector<Vec3> distinct(points.begin(), points.end());
    const auto before = [](const Vec3& a, const Vec3& b) { return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z))); };
    std::sort(distinct.begin(), distinct.end(), before);
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    Obb best = principal_box(distinct);
    // the face directions, each once (a normal and its opposite are one direction); a smooth object has many, and
    // its principal axes serve it well
    constexpr std::size_t few = 64;
    std::vector<Vec3> directions;
    for (const Vec3& n : normals) {
        if (!std::isfinite(n.x + n.y + n.z) || !(glm::length(n) > 0.5)) continue;
        const bool seen = std::any_of(directions.begin(), directions.end(), [&](const Vec3& d) { return std::abs(glm::dot(d, n)) > 1 - 1e-9; });
        if (!seen) directions.push_back(n);
        if (directions.size() > few) return best;
    }
    for (const Vec3& n : directions)
        if (const Obb b = box_on_face(n, distinct); b.volume() < best.volume()) best = b;
    return best;
}

}  // namespace hsr::algo
