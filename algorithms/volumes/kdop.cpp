// SPDX-License-Identifier: MIT
#include "volumes/kdop.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "geometry/half_space_cut.h"
#include "geometry/interval.h"

namespace hsr::algo {

namespace {


// A convex polygon's part on the side n·x ≤ c (Sutherland–Hodgman against one plane); the points made on the plane
// are added to `cut`.
std::vector<Vec3> clip_face(const std::vector<Vec3>& face, const Vec3& n, double c, std::vector<Vec3>& cut) {
    std::vector<Vec3> out = cut_polygon(face, [&](const Vec3& p) { return c - glm::dot(n, p); }, {.on_boundary = &cut});
    return out.size() >= 3 ? out : std::vector<Vec3>{};
}

// The points on the plane with normal n, in counter-clockwise order seen from the side n points to (duplicates
// dropped): the cap a clip leaves.
std::vector<Vec3> cap(std::vector<Vec3> points, const Vec3& n) {
    if (points.size() < 3) return {};
    Vec3 centre(0);
    for (const Vec3& p : points) centre += p;
    centre /= double(points.size());
    const Vec3 u = glm::normalize(std::abs(n.x) < 0.9 * glm::length(n) ? glm::cross(n, Vec3(1, 0, 0)) : glm::cross(n, Vec3(0, 1, 0)));
    const Vec3 v = glm::normalize(glm::cross(n, u));
    std::sort(points.begin(), points.end(), [&](const Vec3& a, const Vec3& b) {
        return std::atan2(glm::dot(a - centre, v), glm::dot(a - centre, u)) < std::atan2(glm::dot(b - centre, v), glm::dot(b - centre, u));
    });
    std::vector<Vec3> unique;
    double scale = 0;
    for (const Vec3& p : points) scale = std::max(scale, glm::length(p - centre));
    for (const Vec3& p : points)
        if (unique.empty() || glm::length(p - unique.back()) > 1e-12 * scale) unique.push_back(p);
    while (unique.size() > 1 && glm::length(unique.front() - unique.back()) <= 1e-12 * scale) unique.pop_back();
    return unique.size() >= 3 ? unique : std::vector<Vec3>{};
}

}  // namespace

bool valid_k(int k) { return k == 6 || k == 14 || k == 18 || k == 26; }

std::vector<Vec3> kdop_directions(int k) {
    std::vector<Vec3> d = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    if (k == 14 || k == 26) d.insert(d.end(), {{1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}});
    if (k == 18 || k == 26) d.insert(d.end(), {{1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, -1, 0}, {1, 0, -1}, {0, 1, -1}});
    return d;
}

KDop kdop_of(std::span<const Vec3> points, int k) {
    KDop dop{k, kdop_directions(k), {}, {}};
    dop.lo.assign(dop.directions.size(), std::numeric_limits<double>::infinity());
    dop.hi.assign(dop.directions.size(), -std::numeric_limits<double>::infinity());
    for (const Vec3& p : points)
        for (std::size_t i = 0; i < dop.directions.size(); ++i) {
            const double s = glm::dot(dop.directions[i], p);
            dop.lo[i] = std::min(dop.lo[i], s), dop.hi[i] = std::max(dop.hi[i], s);
        }
    return dop;
}

std::vector<std::vector<Vec3>> kdop_faces(const KDop& dop) {
    if (dop.directions.size() < 3 || !(dop.lo[0] <= dop.hi[0])) return {};
    // the axis box (directions 0–2 are the axes), each face wound counter-clockwise from outside
    const Vec3 lo(dop.lo[0], dop.lo[1], dop.lo[2]), hi(dop.hi[0], dop.hi[1], dop.hi[2]);
    const auto c = [&](int x, int y, int z) { return Vec3(x ? hi.x : lo.x, y ? hi.y : lo.y, z ? hi.z : lo.z); };
    std::vector<std::vector<Vec3>> faces = {
        {c(0, 0, 0), c(0, 0, 1), c(0, 1, 1), c(0, 1, 0)}, {c(1, 0, 0), c(1, 1, 0), c(1, 1, 1), c(1, 0, 1)},  // −x, +x
        {c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)}, {c(0, 1, 0), c(0, 1, 1), c(1, 1, 1), c(1, 1, 0)},  // −y, +y
        {c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0)}, {c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)},  // −z, +z
    };
    for (std::size_t i = 3; i < dop.directions.size(); ++i)
        for (const double sign : {1.0, -1.0}) {  // n·x ≤ hi, then −n·x ≤ −lo
            const Vec3 n = sign * dop.directions[i];
            const double limit = sign > 0 ? dop.hi[i] : -dop.lo[i];
            std::vector<Vec3> cut;
            std::vector<std::vector<Vec3>> kept;
            for (const auto& f : faces)
                if (auto part = clip_face(f, n, limit, cut); !part.empty()) kept.push_back(std::move(part));
            if (auto lid = cap(cut, n); !lid.empty()) kept.push_back(std::move(lid));
            faces = std::move(kept);
        }
    return faces;
}

std::optional<Interval> ray_through(const Aabb& box, const Vec3& o, const Vec3& d) {
    if (box.empty()) return std::nullopt;
    Interval t{0, std::numeric_limits<double>::infinity()};
    for (int a = 0; a < 3; ++a)
        if (!narrow_to_slab(t, box.lo[a], box.hi[a], o[a], d[a])) return std::nullopt;
    return t;
}

std::optional<Interval> ray_through(const Sphere& s, const Vec3& o, const Vec3& d) {
    // |o + t·d − c|² = r²: a·t² + 2b·t + c0 = 0
    const Vec3 m = o - s.centre;
    const double a = glm::dot(d, d), b = glm::dot(m, d), c0 = glm::dot(m, m) - s.radius * s.radius;
    if (a == 0) return c0 <= 0 ? std::optional(Interval{0, 0}) : std::nullopt;
    const double disc = b * b - a * c0;
    if (disc < 0) return std::nullopt;
    const double root = std::sqrt(disc);
    const double t0 = (-b - root) / a, t1 = (-b + root) / a;
    if (t1 < 0) return std::nullopt;
    return Interval{std::max(t0, 0.0), t1};
}

std::optional<Interval> ray_through(const Obb& box, const Vec3& o, const Vec3& d) {
    Interval t{0, std::numeric_limits<double>::infinity()};
    const Vec3 m = o - box.centre;
    for (int a = 0; a < 3; ++a)
        if (!narrow_to_slab(t, -box.half[a], box.half[a], glm::dot(box.axes[std::size_t(a)], m), glm::dot(box.axes[std::size_t(a)], d)))
            return std::nullopt;
    return t;
}

std::optional<Interval> ray_through(const KDop& dop, const Vec3& o, const Vec3& d) {
    Interval t{0, std::numeric_limits<double>::infinity()};
    for (std::size_t i = 0; i < dop.directions.size(); ++i)
        if (!narrow_to_slab(t, dop.lo[i], dop.hi[i], glm::dot(dop.directions[i], o), glm::dot(dop.directions[i], d))) return std::nullopt;
    return t;
}

}  // namespace hsr::algo
