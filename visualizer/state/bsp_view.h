// SPDX-License-Identifier: MIT
// What a BSP lesson shows, as plain data: the polygons (inputs, then split parts as they appear), the tree as it
// grows, and the painter's order as the traversal draws. Changed only by reduce().
#pragma once

#include <optional>
#include <vector>

#include "bsp/bsp_scene.h"

namespace hsr::viz {

struct BspPolygonView {
    std::int32_t source;                  // the scene's id
    std::string label;                    // "3", "3f", "3fb"
    algo::VertexList vertices;            // world space, shared (never changed once made)
    bool replaced = false;                // split into two parts
    int node = -1;                        // the node it is kept at, once decided
    std::optional<algo::PolygonSide> side;  // its side of the current node's plane, once classified there
    int drawn = 0;                        // its number in the painter's order (0: not drawn yet)
};

struct BspNodeView {
    algo::Plane plane;
    int parent = -1;
    algo::Side side_of_parent = algo::Side::front;
    int depth = 0;
    int splitter = -1;
    int front = -1, back = -1;
    std::optional<algo::Side> eye_side;  // set when the traversal classifies the eye here
};

struct BspView {
    std::vector<BspPolygonView> polygons;
    std::vector<BspNodeView> nodes;
    int current_node = -1;
    int current_polygon = -1;
    int drawn = 0;          // polygons painted so far
    int splits = 0, depth = 0;
    bool built = false, bounded = false, two_d = false;
    algo::Vec3 eye{0};
    algo::Order order = algo::Order::back_to_front;  // DisplayBSP's
    // The polygons given a side since the current node's splitter was chosen: the next node clears only these
    // (clearing every polygon's side per node made a large build quadratic to watch).
    std::vector<algo::BspPolygonId> sided;
};

BspView initial_view(const algo::BspJob& job);
void reduce(BspView& view, const algo::BspEvent& event);
std::size_t approx_bytes(const BspView& view);
std::vector<std::string> labels(const BspView& view);
// Names polygons by the view's labels, for describe(); the view must outlive it.
algo::PolygonNamer namer(const BspView& view);

}  // namespace hsr::viz
