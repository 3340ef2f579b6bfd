// SPDX-License-Identifier: MIT
// Bounding volumes of a group of primitives (the lecture: "simple shapes that enclose an object": the axis-aligned
// box, the sphere, the oriented box), and the void space each leaves: the part of its volume the object does not
// fill, which is what makes a cheap test say "maybe visible" for an object that is not.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include "core/plane.h"

namespace hsr::algo {

struct Aabb {
    Vec3 lo{1e300}, hi{-1e300};  // empty until something is added
    void add(const Vec3& p);
    void add(const Aabb& b);
    [[nodiscard]] bool empty() const { return lo.x > hi.x; }
    [[nodiscard]] Vec3 centre() const { return (lo + hi) / 2.0; }
    [[nodiscard]] Vec3 size() const { return hi - lo; }
    [[nodiscard]] double volume() const;
    [[nodiscard]] Vec3 corner(int k) const { return {k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z}; }
    [[nodiscard]] bool contains(const Aabb& b) const;
    bool operator==(const Aabb&) const = default;
};

struct Sphere {
    Vec3 centre{0};
    double radius = 0;
    [[nodiscard]] double volume() const;
};

struct Obb {
    Vec3 centre{0};
    std::array<Vec3, 3> axes{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};  // orthonormal
    Vec3 half{0};                                                          // half-extents along the axes
    [[nodiscard]] double volume() const { return 8 * half.x * half.y * half.z; }
    [[nodiscard]] Vec3 corner(int k) const;
};

Aabb aabb_of(std::span<const Vec3> points);
// Ritter's sphere (two passes: a first guess from distant points, grown to take in every point): within ~5–20 % of
// the smallest.
Sphere sphere_of(std::span<const Vec3> points);
// Axes from the principal components of the distinct points (eigenvectors of their covariance, by Jacobi
// rotations), then the extents along them; given the object's face normals, and when they point in few directions
// (at most 64: a box, a prism), a box with each as one axis and the smallest rectangle across it replaces that one
// where it is smaller (a triangulated box, turned, then gets its own box: principal axes alone are arbitrary for a
// cube and pulled aside by corners that many triangles share). In oriented_box.cpp.
Obb obb_of(std::span<const Vec3> points, std::span<const Vec3> face_normals = {});
// Each polygon's unit normal (Newell's), for obb_of; polygons without area give none.
std::vector<Vec3> face_normals(std::span<const std::vector<Vec3>> polygons);

// The volume a closed, consistently outward-wound triangle or polygon mesh encloses (the divergence theorem: the
// sum of signed tetrahedra from the origin). 0 for an open surface is not guaranteed: call it only on closed meshes.
double enclosed_volume(std::span<const std::vector<Vec3>> polygons);

// The share of a bounding volume the object does not fill: 1 − object volume / bounding volume; nullopt when the
// object is not a closed solid inside it (no positive volume, or more than the bounding volume: an open surface or
// one wound inwards), where a share would be a number without a meaning.
std::optional<double> void_fraction(double bounding_volume, double object_volume);

// The objects of a polygon soup: sets of polygons joined through shared vertices (exactly equal coordinates), each
// listed by the polygons' indices in ascending order, the objects in the order of their first polygon.
std::vector<std::vector<std::size_t>> connected_objects(std::span<const std::vector<Vec3>> polygons);

}  // namespace hsr::algo
