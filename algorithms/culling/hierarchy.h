// SPDX-License-Identifier: MIT
// Hierarchies of bounding volumes over a scene's primitives (the lecture: a BVH, and an octree that "recursively
// subdivides an initial cell into 8 subcells when an elementary cell size is reached or the object complexity
// within a cell is below a certain limit"), built step by step, and culled top-down:
//
//   Cull(node, planes):                      planes: those node's parent was not wholly inside (the clip flags)
//     for each plane in planes:              the box against the plane (its nearest and farthest corners)
//       if node's box is wholly outside it:  reject node and its subtree
//       if wholly inside it:                 drop the plane for the subtree
//     if no plane is left:                   accept node and its subtree without further tests
//     if node's projected size < threshold:  leave node and its subtree out (detail culling)
//     keep node's own primitives whose boxes pass the planes left; Cull(child, planes) for each child
#pragma once

#include <cstdint>
#include <vector>

#include "core/steps.h"
#include "culling/culling_events.h"
#include "scene/scene.h"

namespace hsr::algo {

enum class HierarchyKind : std::uint8_t { bvh, octree };

struct HierarchyNode {
    Aabb box;                              // a BVH's tight box; an octree's cell
    std::int32_t parent = -1;
    std::vector<std::uint32_t> children;
    std::vector<std::uint32_t> primitives;  // held here (a BVH's leaves; an octree's node holds those that fit no child)
    std::uint32_t depth = 0, subtree_primitives = 0;
};

struct Hierarchy {
    HierarchyKind kind = HierarchyKind::bvh;
    std::vector<HierarchyNode> nodes;  // the root is nodes[0] when there are primitives
    std::vector<Aabb> boxes;           // of each primitive
    std::uint32_t depth = 0;
};

struct HierarchyOptions {
    HierarchyKind kind = HierarchyKind::bvh;
    std::uint32_t max_primitives = 4;  // a node with no more is a leaf
    double min_cell = 0;               // octree: a cell no wider is a leaf (0: 1/1024 of the root cell)
    std::uint32_t max_depth = 40;      // a bound: a node this deep is a leaf
};

Steps<HierarchyEvent, Hierarchy> build_hierarchy(std::vector<Aabb> boxes, HierarchyOptions options = {});
// The box of each of the scene's polygons, in order: what a hierarchy over the scene is built from.
std::vector<Aabb> polygon_boxes(const Scene& scene);

struct HierarchyCullOptions {
    bool frustum = true;
    double detail_pixels = 0;    // leave out nodes projected smaller than this many pixels across (0: off)
    int viewport_height = 600;   // pixels, for the projected size
    // per primitive: did it reach this stage (earlier stages of a pipeline kept it)? Empty: all did. The others are
    // neither kept nor counted as outside or too small.
    std::vector<std::uint8_t> candidates;
};

struct HierarchyCull {
    std::vector<std::uint8_t> kept;  // per primitive
    std::uint32_t nodes_tested = 0, plane_tests = 0;
    std::uint32_t outside = 0, too_small = 0;  // primitives left out by each (candidates only)
};

// The hierarchy must outlive the machine.
Steps<HierarchyCullEvent, HierarchyCull> cull_hierarchy(const Hierarchy* hierarchy, Camera camera, HierarchyCullOptions options = {});

// Does the box pass every plane of `frustum` whose bit is set in `mask` (not wholly behind one)? Counts the plane
// tests made into *tests when given. A partial node's own primitives are kept or left out by this.
bool box_passes(const Aabb& box, const std::vector<Plane>& frustum, std::uint8_t mask, std::uint32_t* tests = nullptr);
// Box against plane, by its p- and n-vertices: −1 wholly behind (outside), +1 wholly in front (inside), 0 across.
int box_side(const Aabb& box, const Plane& plane);
// The box's projected size in pixels (its bounding sphere's diameter over its distance, in pixels of the height);
// infinite when the sphere reaches the eye's plane.
double projected_pixels(const Aabb& box, const Camera& camera, int viewport_height);

}  // namespace hsr::algo
