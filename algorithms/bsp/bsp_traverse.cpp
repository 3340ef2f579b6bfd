// SPDX-License-Identifier: MIT
// DisplayBSP, as the lecture gives it: if the eye is in front of the node's plane, display the back subtree, the
// node's polygons, then the front subtree; otherwise the other way round. The polygons come out back to front
// (the painter's order); front to back swaps the sides.
#include "bsp/bsp_tree.h"

#include <glm/geometric.hpp>

#include "core/numeric.h"

namespace hsr::algo {
namespace {

// DisplayBSP(root) with the recursion's stack kept by hand (as in the build: a recursive generator would pass each
// event up through every level of a deep tree). Each entry is a call still to make, DisplayBSP(node), or the
// middle of one, "draw the node's polygons"; they are pushed in reverse so they run far side, node, near side.
struct Call {
    BspNodeId node;
    bool draw_polygons = false;  // the middle of the node's call: its far side is done
    Side eye_side = Side::front;
};

Steps<BspEvent, std::vector<BspPolygonId>> traversal(const BspTree* t, Viewpoint eye, Order order) {
    std::vector<BspPolygonId> drawn;
    std::vector<Call> calls{{t->root}};  // the top runs next
    while (!calls.empty()) {
        const Call call = calls.back();
        calls.pop_back();
        if (call.node < 0) continue;
        const BspNode& node = t->nodes[std::size_t(call.node)];
        if (call.draw_polygons) {
            for (BspPolygonId p : node.polygons) {
                drawn.push_back(p);
                co_yield PolygonDrawn{call.node, p, std::uint32_t(drawn.size()), call.eye_side, node.front < 0 && node.back < 0};
            }
            continue;
        }
        const double distance = eye.toward_eye ? glm::dot(node.plane.n, *eye.toward_eye) : node.plane.distance(eye.at);
        const Side side = eye_side(node.plane, eye, node_tolerance(*t, node, eye.at));
        co_yield EyeClassified{call.node, side, order, distance, node.polygons.empty() ? -1 : node.polygons.front()};

        // The far side first: behind the plane when the eye is in front (or on it: then either order is right,
        // since the node's polygons are seen edge-on)
        BspNodeId far = side == Side::back ? node.front : node.back;
        BspNodeId near = side == Side::back ? node.back : node.front;
        if (order == Order::front_to_back) std::swap(far, near);
        calls.push_back({near});
        calls.push_back({call.node, true, side});
        calls.push_back({far});
    }
    co_yield TraversalFinished{std::uint32_t(drawn.size())};
    co_return drawn;
}

}  // namespace

Viewpoint Viewpoint::at_infinity(Vec3 eye, Vec3 toward_eye) {
    Viewpoint v(eye);
    v.toward_eye = glm::normalize(toward_eye);
    return v;
}

Side eye_side(const Plane& plane, const Viewpoint& eye, Tolerance tol) {
    if (!eye.toward_eye) return classify(plane, eye.at, tol);
    const double cosine = glm::dot(plane.n, *eye.toward_eye);  // both unit length
    return cosine > 1e-12 ? Side::front : cosine < -1e-12 ? Side::back : Side::on;
}

Steps<BspEvent, std::vector<BspPolygonId>> traverse_bsp(const BspTree* tree, Viewpoint eye, Order order) {
    require_finite(glm::dvec4(eye.at, 1.0), "eye");
    if (eye.toward_eye && !(glm::length(*eye.toward_eye) > 0.5)) throw InvalidInput("eye: a view direction of no length");
    if (eye.toward_eye) require_finite(glm::dvec4(*eye.toward_eye, 0.0), "eye direction");
    return traversal(tree, eye, order);
}

Location locate(const BspTree& tree, const Vec3& p) {
    Location where;
    for (BspNodeId n = tree.root; n >= 0;) {
        const BspNode& node = tree.nodes[std::size_t(n)];
        const Side side = classify(node.plane, p, node_tolerance(tree, node, p));
        where.path.push_back(n);
        where.sides.push_back(side);
        n = side == Side::back ? node.back : node.front;  // a point on the plane counts as in front
    }
    return where;
}

}  // namespace hsr::algo
