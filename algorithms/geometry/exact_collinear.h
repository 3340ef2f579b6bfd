// SPDX-License-Identifier: MIT
// Whether points lie on one line, decided exactly: a polygon of no area (its vertices on one line or at one point)
// is told from a sliver of any area, however thin, with no tolerance.
#pragma once

#include <span>

#include <glm/vec3.hpp>

namespace hsr::algo {

using Vec3 = glm::dvec3;

// True when every point lies on the line through the first two distinct ones (or all coincide). Exact for
// coordinates whose products neither overflow nor underflow (the polygon is scaled by a power of two, which is exact,
// so that its largest coordinate is near 1: exact whenever its coordinates span less than about 2^±480).
bool collinear_exactly(std::span<const Vec3> points);

}  // namespace hsr::algo
