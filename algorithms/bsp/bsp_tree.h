// SPDX-License-Identifier: MIT
// A BSP tree (the lecture's BuildBSP / DisplayBSP), in 3D for polygons and in 2D for segments in the plane z = 0
// (the classroom picture): a segment is a 2-vertex polygon whose plane is the vertical plane through it.
#pragma once

#include <string>
#include <optional>
#include <span>
#include <vector>

#include "bsp/bsp_events.h"
#include "core/steps.h"

namespace hsr::algo {

struct BspPolygon {
    std::int32_t source;         // the scene's id of the polygon it is (a part of)
    std::string label;           // "3", or "3f" / "3b" for the parts of a split, "3fb" for a part of a part
    std::vector<Vec3> vertices;  // world space; 2 vertices for a 2D segment
    Plane plane;
};

struct BspNode {
    Plane plane;                        // the splitter's plane
    std::vector<BspPolygonId> polygons; // the splitter and the polygons coplanar with it
    BspNodeId front = -1, back = -1;
    std::uint32_t depth = 0;            // the root is 0
};

struct BspTree {
    std::vector<BspPolygon> polygons;  // inputs first, then parts as they are made
    std::vector<BspNode> nodes;        // in the order they are made; the root is nodes[0] when not empty
    BspNodeId root = -1;
    Tolerance tolerance;               // ε of the whole scene's extent; a test between polygons uses theirs (pair_tolerance)
    std::uint32_t splits = 0, depth = 0;  // depth: of the deepest node, counting the root as 1
    std::uint64_t classifications = 0;    // polygons classified against a splitter's plane, in all
    bool bounded = false;                 // a bound stopped the build; the tree is still a valid BSP of what it has
    std::vector<std::string> labels() const;
    // The polygons the nodes hold, the ones a traversal draws: the inputs less those split, plus the parts kept
    // (a part split again counts as its parts). `polygons` holds the split ones too.
    std::size_t held() const;
};

struct BspInput {
    std::int32_t id = 0;
    std::vector<Vec3> vertices;  // 3 or more (a planar polygon), or 2 (a 2D segment in z = 0)
};

struct BspOptions {
    SplitterRule splitter = SplitterRule::first;
    double balance_weight = 1.0;      // weighted rule: score = balance_weight·|front − back| + split_weight·spanning
    double split_weight = 8.0;
    std::uint32_t max_depth = 4096;   // bounds: the build ends with BspBoundReached at any of them
    std::uint32_t max_polygons = 4u << 20;
    // Polygons classified in all: by default 256 per input polygon (a tree of n polygons whose polygons lie d deep
    // on average classifies about n·d), at least 2^24 (a chain of 5,000 polygons, the worst order, fits) and at most
    // 2^28 (about 13 s at 20 million a second): each classification is real work, and without this bound a poor
    // tree of 10^6 polygons ran 90 s before its polygon bound.
    std::optional<std::uint32_t> max_classifications;
};

// Validates (InvalidInput naming the polygon: NaN, infinity, fewer than 2 vertices, no area), then returns the
// lazy machine. Each test uses ε = 1e-9 × the size of the smaller of the two polygons it compares, plus the
// rounding at their coordinates (pair_tolerance, Tolerance::for_pair).
Steps<BspEvent, BspTree> build_bsp(std::vector<BspInput> polygons, BspOptions options = {});

// Where DisplayBSP looks from: a point (a perspective camera's eye), or an eye at infinity (an orthographic camera:
// every ray runs along the view direction, so the eye is on the side of a plane that direction points back into).
struct Viewpoint {
    Vec3 at{0};                         // the eye (for an orthographic camera: where it is drawn)
    std::optional<Vec3> toward_eye;     // orthographic: the unit direction from the scene back to the eye, which decides
    Viewpoint(Vec3 eye = Vec3(0)) : at(eye) {}  // NOLINT(google-explicit-constructor): a point is a viewpoint
    static Viewpoint at_infinity(Vec3 eye, Vec3 toward_eye);
    bool operator==(const Viewpoint&) const = default;
};

// ε for testing polygon `b` against polygon `a`'s plane (or a point against a node's): their own sizes, not the scene's.
Tolerance pair_tolerance(const BspTree& tree, BspPolygonId a, std::span<const Vec3> b);
// ε for a point against a node's plane (the node's first polygon and the point).
Tolerance node_tolerance(const BspTree& tree, const BspNode& node, const Vec3& p);

// The eye's side of a plane: by its signed distance for a point, by the cosine with the normal for an eye at infinity
// (on the plane: the plane holds the view direction, and its polygons are seen edge-on).
Side eye_side(const Plane& plane, const Viewpoint& eye, Tolerance tol);

// DisplayBSP: at each node classify the eye, visit the far side, draw the node's polygons, visit the near side
// (front to back swaps the sides). The tree must outlive the machine.
Steps<BspEvent, std::vector<BspPolygonId>> traverse_bsp(const BspTree* tree, Viewpoint eye,
                                                        Order order = Order::back_to_front);

// The leaf region holding p: the path of nodes from the root and the side taken at each, in O(depth).
struct Location {
    std::vector<BspNodeId> path;
    std::vector<Side> sides;
};
Location locate(const BspTree& tree, const Vec3& p);

}  // namespace hsr::algo
