// SPDX-License-Identifier: MIT
// What a ray-casting lesson shows: the image filled ray by ray, the current ray, the grid cells it has walked (or
// the octree nodes it has entered), the primitive tested last and the nearest hit so far.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "raycast/ray_cast.h"

namespace hsr::viz {

// An octree cell as the build has told it so far.
struct OctreeCellView {
    algo::Vec3 lo{0}, hi{0};
    int depth = 0;
    std::uint32_t primitives = 0;
    bool split = false, leaf = false;  // neither while it is being examined
    algo::OctreeStop reason = algo::OctreeStop::few_primitives;  // why it stayed a leaf
};

struct RayView {
    algo::Viewport viewport;
    algo::Acceleration acceleration = algo::Acceleration::grid;
    std::shared_ptr<const algo::Grid> grid;  // the cells the machine walks (grid lessons), never changed
    std::vector<std::int32_t> owner;         // scene polygon index seen per pixel, −1 background (y down)
    int ray_x = -1, ray_y = -1;
    algo::Vec3 origin{0}, direction{0};  // world space; t = 0 near plane, t = 1 far plane
    std::vector<glm::ivec3> cells;       // walked by the current ray, in order
    int nodes = 0;                       // octree nodes entered by the current ray
    int entered = -1;                    // the octree node the current ray entered last
    std::vector<OctreeCellView> octree;  // the octree's cells in node order, as BuildOctree has made them so far
    int examined = -1;                   // the cell BuildOctree examined last
    bool octree_built = false;
    int tested = -1;                     // scene polygon index tested last
    bool tested_hit = false;
    double tested_t = 0;
    int nearest = -1;  // the nearest hit so far on the current ray
    double nearest_t = 2;
    std::uint32_t ray_tests = 0;
    std::uint64_t tests = 0, rays = 0;
    bool done = false, bounded = false;
};

void reduce(RayView& view, const algo::RayCastEvent& event);
std::size_t approx_bytes(const RayView& view);

}  // namespace hsr::viz
