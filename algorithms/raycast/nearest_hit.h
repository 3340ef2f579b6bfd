// SPDX-License-Identifier: MIT
// The reference the hidden-surface algorithms are checked against: for one ray, the nearest intersection over all
// primitives, in double precision (the lecture's RayCasting, for one pixel). Polygons are planar with 3 or more
// vertices; 2-vertex "polygons" are 2D segments in z = 0, hit by rays in that plane.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/plane.h"

namespace hsr::algo {

struct Ray {
    Vec3 origin;
    Vec3 direction;  // need not be unit
};

// The parameter t > 0 at which the ray meets the polygon (or segment), if it does.
std::optional<double> hit(const Ray& ray, std::span<const Vec3> polygon, const Plane& plane);

struct NearestHit {
    std::size_t index;  // into the polygons given
    double t;
};
std::optional<NearestHit> nearest_hit(const Ray& ray, std::span<const std::vector<Vec3>> polygons,
                                      std::span<const Plane> planes);

}  // namespace hsr::algo
