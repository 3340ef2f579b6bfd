// SPDX-License-Identifier: MIT
// The 2D polygon ideas every family shares, in one place: the cross product of two vectors in the plane, the turn
// of three points, the shoelace (signed) area and the convex hull.
//
// Conventions: y up, so a positive cross product or area means counter-clockwise (on a screen with y down it means
// clockwise). The area functions take any polygon whose points have .x and .y (glm::dvec2, a 3D point, whose
// shadow on z = 0 they measure, or the raster's integer sub-pixel vertices) and sum in the same order as the copies
// they replaced, so every result is the same to the last bit.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>

namespace hsr::algo {

// The 2D cross product a × b (the z of the 3D one): twice the signed area of the triangle 0, a, b.
constexpr double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// Which way a → b → c turns: > 0 counter-clockwise (c left of the line a → b), < 0 clockwise, 0 in a line.
// Twice the signed area of the triangle a, b, c, measured from a.
constexpr double orientation(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) { return cross(b - a, c - a); }

// The shoelace formula: twice the signed area, Σ xᵢ·yᵢ₊₁ − xᵢ₊₁·yᵢ over the edges i → i+1, from the first edge
// to the closing one. 0 for fewer than 3 points.
template <class Polygon>
auto twice_signed_area(const Polygon& p) {
    decltype(p[0].x * p[0].y) twice{};
    for (std::size_t i = 0; i < p.size(); ++i) {
        const auto& a = p[i];
        const auto& b = p[(i + 1) % p.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return twice;
}

// The signed area (> 0 counter-clockwise).
template <class Polygon>
double signed_area(const Polygon& p) { return twice_signed_area(p) / 2.0; }

// The area, whichever way round.
template <class Polygon>
double area(const Polygon& p) { return std::abs(twice_signed_area(p)) / 2.0; }

// The shoelace formula about the first vertex, not the origin, as a fan of triangles: a small polygon far from
// (0, 0) (a sliver of line space 1e-9 wide) has an area below the rounding of products taken about the origin.
double area_about_first_vertex(const std::vector<glm::dvec2>& p);

// The convex hull of points in the plane, counter-clockwise, without collinear points (Andrew's monotone chain).
// Fewer than 3 points come back (sorted, without duplicates) when they have no area.
std::vector<glm::dvec2> convex_hull(std::vector<glm::dvec2> points);

}  // namespace hsr::algo
