// SPDX-License-Identifier: MIT
// k-DOPs, "polyhedra whose faces may only have predefined orientations" (the Greek notes, Bounding Volumes (5)):
// for each of k/2 fixed directions n, the slab min ≤ n·x ≤ max that holds the points. k = 6 is the axis-aligned box;
// 14 adds the four corner diagonals (±1, ±1, ±1), 18 the six edge diagonals (±1, ±1, 0), 26 both. Every direction
// of the 6-DOP is one of the 14-DOP's, and every one of those is one of the 26-DOP's, so 6 ⊇ 14 ⊇ 26 ⊇ the points'
// convex hull: the progressive hulls of the notes (outer hulls simpler, inner ones tighter).
#pragma once

#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "core/plane.h"
#include "culling/bounding_volume.h"
#include "geometry/interval.h"

namespace hsr::algo {

struct KDop {
    int k = 6;
    std::vector<Vec3> directions;  // k/2 of them, not unit (integer components: exact dot products for integer points)
    std::vector<double> lo, hi;    // per direction: the slab of n·x
};

bool valid_k(int k);  // 6, 14, 18 or 26
std::vector<Vec3> kdop_directions(int k);
KDop kdop_of(std::span<const Vec3> points, int k);

// The k-DOP as a closed polyhedron: its faces, each a convex polygon wound counter-clockwise seen from outside
// (the axis box clipped by every other slab). For drawing, and for its volume (enclosed_volume).
std::vector<std::vector<Vec3>> kdop_faces(const KDop& dop);

// Where a ray o + t·d (t ≥ 0) is inside a volume: [t_enter, t_exit], or nothing when it misses. The slab test for
// boxes and k-DOPs (in the box's own axes for an OBB), the quadratic for a sphere.
std::optional<Interval> ray_through(const Aabb& box, const Vec3& o, const Vec3& d);
std::optional<Interval> ray_through(const Sphere& s, const Vec3& o, const Vec3& d);
std::optional<Interval> ray_through(const Obb& box, const Vec3& o, const Vec3& d);
std::optional<Interval> ray_through(const KDop& dop, const Vec3& o, const Vec3& d);

}  // namespace hsr::algo
