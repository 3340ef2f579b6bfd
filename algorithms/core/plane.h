// SPDX-License-Identifier: MIT
// Point-versus-plane and polygon-versus-plane classification: the one predicate every algorithm that sorts
// geometry by a plane uses (BSP build and traversal, depth sort's tests 3 and 4, portals), and its one tolerance.
//
// Tolerance policy: a point is "on" a plane when its signed distance is within ε = 1e-9 × the scene's extent
// (the side of its bounding box). Scaling with the extent is what keeps a scene at coordinates around 1e6 from
// being split by rounding noise a fixed ε would see as geometry; 1e-9 stays far above double rounding
// (≈ 1e-16 × extent) and far below any feature a lesson draws.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include <span>

#include <glm/vec3.hpp>

namespace hsr::algo {

using Vec3 = glm::dvec3;

// n · x + d = 0 with |n| = 1: d is minus the distance of the plane from the origin along n; "front" is where n points.
struct Plane {
    Vec3 n{0, 0, 1};
    double d = 0;
    [[nodiscard]] double distance(const Vec3& p) const;  // signed, world units
    bool operator==(const Plane&) const = default;
};

struct Tolerance {
    double epsilon = 1e-9;  // world units
    static constexpr double relative = 1e-9;  // ε as a share of the size of the numbers compared
    static Tolerance for_extent(double extent) { return {relative * (extent > 0 ? extent : 1.0)}; }
    // For a test between these points (a polygon against another's plane, an eye against a node's): ε relative to
    // their largest coordinate. The rounding in n · x + d grows with |x| and |d|, so this covers it, and a giant
    // polygon elsewhere in the scene changes nothing here.
    static Tolerance for_points(std::span<const Vec3> a, std::span<const Vec3> b = {});
    // For a test of `tested` (a polygon, or a point) against the plane of polygon `planar`: "on the plane" at the
    // scale of the smaller of the two (1e-9 of its size: a polygon tilted a hair out of a neighbour's plane is not
    // split into slivers), plus what rounding leaves uncertain (n · x + d at their coordinates, and a plane through
    // points of magnitude M known to about M · 2^-52). Not the larger one's size: beside a quad 1e10 across, that
    // made every unit triangle within 10 units of its plane "on" it, painted in the wrong order.
    static Tolerance for_pair(std::span<const Vec3> planar, std::span<const Vec3> tested);
};

enum class Side : std::uint8_t { front, back, on };
enum class PolygonSide : std::uint8_t { front, back, coplanar, spanning };

Side classify(const Plane& plane, const Vec3& p, Tolerance tol);
PolygonSide classify(const Plane& plane, std::span<const Vec3> polygon, Tolerance tol);

// The part of the polygon in front of the plane and the part behind it (vertices on the plane go to both), in
// order. For a spanning polygon both are non-empty.
struct SplitParts {
    std::vector<Vec3> front, back;
};
SplitParts split(const Plane& plane, std::span<const Vec3> polygon, Tolerance tol);

// The plane of a polygon by Newell's method (robust for slightly non-planar polygons), front side by the
// counter-clockwise winding; for a 2-vertex "polygon" (a 2D segment in z = 0) the vertical plane through it, whose
// front is the segment's left side. Returns false when the polygon has no area (or the segment no length).
bool plane_of(std::span<const Vec3> polygon, Plane& out);

// Area of a planar polygon (length for a 2-vertex one).
double measure(std::span<const Vec3> polygon);
// The mean of the vertices (for labels and arrows; not the area centroid).
Vec3 centroid(std::span<const Vec3> polygon);

std::string_view to_string(Side s);
std::string_view to_string(PolygonSide s);

}  // namespace hsr::algo
