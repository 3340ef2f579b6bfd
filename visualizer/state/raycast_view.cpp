// SPDX-License-Identifier: MIT
#include "state/raycast_view.h"

#include "core/overloaded.h"

namespace hsr::viz {

using namespace hsr::algo;

void reduce(RayView& v, const RayCastEvent& event) {
    std::visit(overloaded{
                   [&](const RayStarted& e) {
                       v.ray_x = e.x, v.ray_y = e.y, v.origin = e.origin, v.direction = e.direction;
                       v.cells.clear(), v.nodes = 0, v.entered = -1, v.tested = -1, v.nearest = -1, v.nearest_t = 2, v.ray_tests = 0;
                   },
                   [&](const CellEntered& e) { v.cells.push_back(e.cell); },
                   [&](const NodeEntered& e) { ++v.nodes, v.entered = int(e.node); },
                   [&](const PrimitiveTested& e) {
                       v.tested = int(e.index), v.tested_hit = e.hit, v.tested_t = e.t;
                       ++v.ray_tests, ++v.tests;
                   },
                   [&](const NearerHitFound& e) { v.nearest = int(e.index), v.nearest_t = e.t; },
                   [&](const RayFinished& e) {
                       v.owner[std::size_t(e.y) * std::size_t(v.viewport.width) + std::size_t(e.x)] = e.index;
                       v.nearest = e.index, v.nearest_t = e.t, v.tested = -1;
                       ++v.rays;
                   },
                   [&](const CastFinished&) { v.done = true, v.ray_x = v.ray_y = -1, v.cells.clear(); },
                   [&](const CastStepBoundReached&) { v.bounded = true; },
                   [&](const OctreeCellExamined& e) {
                       if (v.octree.size() <= e.node) v.octree.resize(std::size_t(e.node) + 1);
                       OctreeCellView& c = v.octree[e.node];
                       c.lo = e.lo, c.hi = e.hi, c.depth = e.depth, c.primitives = e.primitives;
                       v.examined = int(e.node);
                   },
                   [&](const OctreeCellSplit& e) {
                       if (e.node < v.octree.size()) v.octree[e.node].split = true;
                   },
                   [&](const OctreeLeafMade& e) {
                       if (e.node < v.octree.size()) v.octree[e.node].leaf = true, v.octree[e.node].reason = e.reason;
                   },
                   [&](const OctreeBuilt&) { v.octree_built = true, v.examined = -1; },
               },
               event);
}

std::size_t approx_bytes(const RayView& v) {
    return sizeof(RayView) + v.owner.capacity() * sizeof(std::int32_t) + v.cells.capacity() * sizeof(glm::ivec3) +
           v.octree.capacity() * sizeof(OctreeCellView);
}

}  // namespace hsr::viz
