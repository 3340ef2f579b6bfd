// SPDX-License-Identifier: MIT
// The machine a BSP lesson plays: build the tree from a scene's polygons (or, for the classroom picture, its
// segments in the plane z = 0), then display it from the camera's eye (DisplayBSP), back to front.
#pragma once

#include "bsp/bsp_tree.h"
#include "scene/scene.h"

namespace hsr::algo {

struct BspJob {
    std::vector<BspInput> polygons;  // in insertion order: the rule "first" takes them as they come
    BspOptions options;
    Viewpoint eye;
    Order order = Order::back_to_front;  // DisplayBSP's; front to back paints only pixels still empty
};

// The camera's eye for DisplayBSP: its position, or for an orthographic camera its direction (the eye at infinity).
Viewpoint viewpoint_of(const Camera& camera);

// Polygons from scene.polygons; when the scene has none, its segments as 2D segments (their z is dropped).
BspJob bsp_job(const Scene& scene, SplitterRule rule);

// Build events, then traversal events; the answer is the painter's order.
Steps<BspEvent, std::vector<BspPolygonId>> bsp_scene(BspJob job);

}  // namespace hsr::algo
