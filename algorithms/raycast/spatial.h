// SPDX-License-Identifier: MIT
// The lectures' spatial subdivision for ray casting: a regular grid walked cell by cell (3D DDA) and an octree.
// Both list, for each cell or leaf, the primitives whose bounding box (padded by 1e-9 of the scene's extent, so
// that a hit on a cell face is listed on both sides) overlaps it.
#pragma once

#include <cmath>

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "core/plane.h"
#include "core/steps.h"
#include "geometry/interval.h"
#include "raycast/nearest_hit.h"
#include "raycast/raycast_events.h"

namespace hsr::algo {

struct Box {
    Vec3 lo{0}, hi{0};
};
Box bounds_of(const std::vector<std::vector<Vec3>>& polygons);  // padded, never flat along an axis

// Where the ray is inside the box, within [t0, t1]; axis-parallel rays divide by nothing.
std::optional<Interval> ray_box(const Ray& ray, const Box& box, double t0, double t1);

struct Grid {
    Box box;
    glm::ivec3 cells{1};  // per axis
    Vec3 size{1};         // of one cell, world units
    std::vector<std::vector<std::uint32_t>> lists;  // primitive indices per cell, x fastest
    const std::vector<std::uint32_t>& at(glm::ivec3 c) const {
        return lists[std::size_t((c.z * cells.y + c.y) * cells.x + c.x)];
    }
    // The cell along axis a holding coordinate v, clamped to the grid (and 0 for NaN): the conversion to int is
    // made only once the value is in range, so that huge or infinite coordinates are no undefined behaviour.
    int cell_of(double v, int a) const {
        const double t = std::floor((v - box.lo[a]) / size[a]);
        if (!(t > 0)) return 0;
        return t >= double(cells[a] - 1) ? cells[a] - 1 : int(t);
    }
};
// per_axis = 0 picks about 2·∛n cells per axis (at most 64).
Grid build_grid(const std::vector<std::vector<Vec3>>& polygons, int per_axis = 0);

struct OctreeNode {
    Box box;
    int depth = 0;
    std::int32_t first_child = -1;  // the 8 children are nodes first_child … first_child + 7; −1 for a leaf
    std::vector<std::uint32_t> primitives;  // leaves only
};
struct Octree {
    std::vector<OctreeNode> nodes;  // nodes[0] is the root
};
// The stopping rules: a cell stays a leaf when it lists max_per_leaf primitives or fewer (the notes' "object
// complexity below a certain limit"), or when its subcells would be smaller than the voxel (edge below `voxel`,
// or deeper than max_depth: the notes' "elementary cell size"), or when the node budget is spent.
struct OctreeOptions {
    std::size_t max_per_leaf = 8;  // split a node holding more
    int max_depth = 8;
    double voxel = 0;              // the elementary cell's edge, world units (0: max_depth alone)
    std::size_t max_nodes = 1 << 20;
};
// BuildOctree as a machine: each cell examined, then split into 8 or made a leaf (and why), depth first.
Steps<RayCastEvent, Octree> octree_build(std::vector<std::vector<Vec3>> polygons, OctreeOptions options = {});
// The same octree, its events unseen.
Octree build_octree(const std::vector<std::vector<Vec3>>& polygons, OctreeOptions options = {});

}  // namespace hsr::algo
