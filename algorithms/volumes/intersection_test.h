// SPDX-License-Identifier: MIT
// The Greek notes' hierarchical intersection test (Bounding Volumes (7)) over a bounding-volume hierarchy of a
// scene's polygons, with the volume chosen: AABB, sphere, OBB, k-DOP (k = 6, 14, 18 or 26) or progressive hulls.
//
//   IntersectionTest(M) {
//       if BottomLevel(M)    return(LLIntersectionTest(M))
//       else if LLIntersectionTest(BoundingBox(M)) {
//           v = false;
//           for each component M→C
//               v = (v || IntersectionTest(M→C));
//           return(v);
//       }
//       else return(false);
//   }
//
// LLIntersectionTest tests its argument exhaustively (a volume, or every primitive of a bottom-level model). The
// answer is whether the ray meets the model at all (the || stops at the first component that says yes): the test a
// shadow ray or a collision query asks. A volume the ray meets with nothing inside it met is a false alarm, the
// price of its void space.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/steps.h"
#include "culling/hierarchy.h"
#include "raycast/nearest_hit.h"
#include "scene/scene.h"
#include "volumes/intersection_events.h"
#include "volumes/kdop.h"

namespace hsr::algo {

struct BoundingOptions {
    VolumeKind volume = VolumeKind::aabb;
    int k = 14;                        // k-DOPs: 6, 14, 18 or 26
    std::uint32_t max_primitives = 4;  // a node with no more is the bottom level
};

// A node's volume of each kind asked for (the others left empty), grown by a relative 1e-9 so that rounding in the
// ray test never loses a primitive on the volume's boundary: a miss must mean a miss.
struct NodeVolume {
    Aabb box;
    Sphere sphere;
    Obb obb;
    std::vector<KDop> dops;  // a k-DOP: one; progressive hulls: the 6-, 14- and 26-DOP, outermost first
    double volume = 0;       // of the kind asked for (hulls: the innermost; k-DOPs: the root only, 0 below it)
};

// The hierarchy over the scene's polygons and each node's volume; what the window draws.
struct BoundingModel {
    BoundingOptions options;
    Hierarchy tree;
    std::vector<std::vector<Vec3>> polygons;  // world space
    std::vector<Plane> planes;
    std::vector<bool> hittable;  // 3 or more vertices with some area
    std::vector<SceneId> ids;
    std::vector<NodeVolume> volumes;  // per node
};
// InvalidInput on a scene without polygons, a k that is not 6, 14, 18 or 26, or max_primitives 0.
BoundingModel bounding_model(const Scene& scene, BoundingOptions options);

// The same ray with a unit direction (scaled by its largest component first, so that 1e300 and 1e-300 survive):
// the machine tests rays in this form, its t are distances.
Ray unit_ray(const Ray& ray);

// The rays a lesson tests: each of the scene's segments, from a through b and on.
std::vector<Ray> rays_of(const Scene& scene);
// InvalidInput when the rays cannot be tested (none, one not finite, one of no direction): looked at before the
// hierarchy is built, which on a large scene takes seconds.
void check_rays(const std::vector<Ray>& rays);

struct IntersectionOptions {
    BoundingOptions bounding;
    std::uint64_t max_steps = std::uint64_t(1) << 32;  // volume and primitive tests before it stops (step bound)
};

struct IntersectionResult {
    std::vector<std::uint8_t> hits;  // per ray
    std::uint64_t volume_tests = 0, primitive_tests = 0, false_alarms = 0;
    bool bounded = false;
};

// Every ray through IntersectionTest(root). The scene and rays are copied into the machine. InvalidInput as for
// bounding_model, and when there is no ray.
Steps<IntersectionEvent, IntersectionResult> intersection_test(Scene scene, std::vector<Ray> rays, IntersectionOptions options = {});

}  // namespace hsr::algo
