// SPDX-License-Identifier: MIT
// The shapes from-point occlusion culling works with, beyond a scene polygon used as it is (the lecture, "From-Point
// Occlusion Culling (3)" and "(5)"):
//
//   proxy:           "a convex polygon perpendicular to the view direction inscribed within the occlusion frustum
//                    of the occluder object or primitive": the convex hull of the object's image, set at the depth of
//                    its farthest point. Every point of it lies behind the object on its own projector, so whatever
//                    its frustum holds, the object hides.
//   solid occluder:  Papaioannou's answer to partial occlusion: a closed convex object as one occluder. Its faces'
//                    frusta leave gaps along its silhouette edges; the proxy of its whole volume has none.
//   occluder fusion: a box is hidden when its image lies in the union of the images of the occluders it lies wholly
//                    behind. One occluder at a time asks for the image inside one of them.
//
// Images live on the view plane: (x/z, y/z) in the camera's frame for a perspective camera, (x, y) for an
// orthographic one, z the depth along the view direction.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "core/plane.h"
#include "geometry/polygon_2d.h"  // convex_hull
#include "culling/hierarchy.h"
#include "scene/scene.h"

namespace hsr::algo {

using Vec2 = glm::dvec2;

// The camera's frame: where a point's image falls and how deep it lies.
struct ViewPlane {
    Vec3 eye, right, up, direction;  // an orthonormal frame, direction from the eye into the scene
    bool orthographic = false;
    double near = 0;
    static ViewPlane of(const Camera& camera);
    double depth(const Vec3& p) const;
    // The image of a point in front of the eye (depth > 0 for a perspective camera); none behind it.
    std::optional<Vec2> image(const Vec3& p) const;
    // The point of depth `depth` whose image is `at`.
    Vec3 point(const Vec2& at, double depth) const;
};

// The proxy of an object given by its vertices: the convex hull of their images at the depth of the farthest. None
// when a vertex lies nearer than the near plane (it would be clipped, and an image behind the eye turns over) or
// the image has no area.
std::optional<std::vector<Vec3>> proxy_of(std::span<const Vec3> vertices, const ViewPlane& view);

// The closed convex solids among a scene's polygons: sets of polygons (indices) joined by shared vertices, each edge
// used by exactly two of them in opposite directions, every vertex on or behind every face's plane. At least four
// faces; a set that is not closed or not convex is no solid (its faces stay planar occluders).
std::vector<std::vector<std::uint32_t>> convex_solids(const Scene& scene);

// Occluder fusion in the view plane: is the convex polygon `image` covered by the union of the convex polygons
// `covers` (counter-clockwise)? A gap narrower than `gap` (view-plane units) is taken as closed: seams between
// occluders that share an edge leave slivers of rounding width. `used` counts the covers that took a part of it.
// Gives up (not covered) beyond `max_pieces` pieces left to cover; `area_left` is then what was left at that point.
struct Coverage {
    bool covered = false;
    std::uint32_t used = 0;
    double area_left = 0;  // of the image, what no cover takes (slivers thinner than `gap` dropped)
};
Coverage covered_by_union(const std::vector<Vec2>& image, std::span<const std::vector<Vec2>> covers, double gap, std::size_t max_pieces = 256);

// The image of a box (the convex hull of its corners' images); none when a corner is not in front of the eye.
std::optional<std::vector<Vec2>> box_image(const Aabb& box, const ViewPlane& view);

}  // namespace hsr::algo
