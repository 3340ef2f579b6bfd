// SPDX-License-Identifier: MIT
#include "culling/bounding_volume.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "geometry/union_find.h"

namespace hsr::algo {

void Aabb::add(const Vec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
void Aabb::add(const Aabb& b) {
    if (!b.empty()) add(b.lo), add(b.hi);
}
double Aabb::volume() const {
    if (empty()) return 0;
    const Vec3 s = size();
    return s.x * s.y * s.z;
}
bool Aabb::contains(const Aabb& b) const {
    return b.lo.x >= lo.x && b.lo.y >= lo.y && b.lo.z >= lo.z && b.hi.x <= hi.x && b.hi.y <= hi.y && b.hi.z <= hi.z;
}

double Sphere::volume() const { return 4.0 / 3.0 * M_PI * radius * radius * radius; }

Vec3 Obb::corner(int k) const {
    return centre + axes[0] * (k & 1 ? half.x : -half.x) + axes[1] * (k & 2 ? half.y : -half.y) + axes[2] * (k & 4 ? half.z : -half.z);
}

Aabb aabb_of(std::span<const Vec3> points) {
    Aabb b;
    for (const Vec3& p : points) b.add(p);
    return b;
}

Sphere sphere_of(std::span<const Vec3> points) {
    if (points.empty()) return {};
    // A first guess: the point farthest from an arbitrary one, and the point farthest from that
    const auto farthest = [&](const Vec3& from) {
        return *std::max_element(points.begin(), points.end(), [&](const Vec3& a, const Vec3& b) {
            return glm::distance(a, from) < glm::distance(b, from);
        });
    };
    const Vec3 a = farthest(points[0]), b = farthest(a);
    Sphere s{(a + b) / 2.0, glm::distance(a, b) / 2};
    // Grow it to take in each point outside: the new sphere touches the old one's far side and the point
    for (const Vec3& p : points) {
        const double d = glm::distance(p, s.centre);
        if (d <= s.radius) continue;
        const double r = (s.radius + d) / 2;
        s.centre += (p - s.centre) * ((r - s.radius) / d);
        s.radius = r;
    }
    s.radius *= 1 + 1e-12;  // rounding must not leave a point a hair outside
    return s;
}

double enclosed_volume(std::span<const std::vector<Vec3>> polygons) {
    double six = 0;
    for (const auto& p : polygons)
        for (std::size_t k = 1; k + 1 < p.size(); ++k) six += glm::dot(p[0], glm::cross(p[k], p[k + 1]));
    return six / 6;
}

std::optional<double> void_fraction(double bounding_volume, double object_volume) {
    // a little slack above the bounding volume: a sphere's or box's volume rounded against a mesh's
    if (!(object_volume > 0) || !(bounding_volume > 0) || object_volume > bounding_volume * (1 + 1e-9)) return std::nullopt;
    return std::max(0.0, 1 - object_volume / bounding_volume);
}

std::vector<std::vector<std::size_t>> connected_objects(std::span<const std::vector<Vec3>> polygons) {
    UnionFind groups(polygons.size());  // over the polygons, joined by any vertex they share
    struct PointHash {
        std::size_t operator()(const std::array<double, 3>& p) const {
            std::size_t h = 0;
            for (const double x : p) h = h * 1000003u ^ std::hash<double>{}(x);
            return h;
        }
    };
    std::unordered_map<std::array<double, 3>, std::size_t, PointHash> first_with;  // a vertex → the first polygon that has it
    for (std::size_t k = 0; k < polygons.size(); ++k)
        for (const Vec3& v : polygons[k]) {
            const auto [at, fresh] = first_with.emplace(std::array<double, 3>{v.x, v.y, v.z}, k);
            if (!fresh) groups.join(k, at->second);
        }
    std::map<std::size_t, std::size_t> object_of_root;
    std::vector<std::vector<std::size_t>> objects;
    for (std::size_t k = 0; k < polygons.size(); ++k) {
        const auto [at, fresh] = object_of_root.emplace(groups.find(k), objects.size());
        if (fresh) objects.emplace_back();
        objects[at->second].push_back(k);
    }
    return objects;
}

}  // namespace hsr::algo
