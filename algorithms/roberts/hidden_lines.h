// SPDX-License-Identifier: MIT
// Roberts' hidden-line algorithm (1963), as the Brown notes give it, object precision: "compare each edge with every
// object — eliminate invisible edges or parts of edges". The objects are convex bodies; complexity worse than O(n²).
//
//   for each body: remove the edges whose two faces both face away from the eye
//   for each edge E left, for each other body B:
//     the points of E that B hides are those whose segment to the eye passes through B's inside
//     remove that part of E
//   draw what is left of every edge
//
// Roberts' own step makes the test linear: after the perspective transform the eye is at infinity and every
// projector is parallel to z, so a point E(t) moved toward the eye by s is E(t) + s·(0, 0, −1), and it lies inside B
// when every face plane of B has h_i(t, s) = n_i · (E(t) + s·v) + d_i < 0: linear in t and s. The (t, s) that
// satisfy all of them form a convex polygon (the rectangle 0 ≤ t ≤ 1, 0 < s clipped by each half-plane); its
// extent in t is the hidden part. A body touching the edge (h = 0) hides nothing.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/plane.h"
#include "core/steps.h"
#include "roberts/roberts_events.h"
#include "scene/scene.h"

namespace hsr::algo {

// A closed convex body: scene polygons joined by shared edges.
struct ConvexBody {
    std::vector<std::uint32_t> faces;  // indices into the scene's polygons
    std::vector<Plane> planes;         // world space, outward
};
struct BodyEdge {
    std::uint32_t body;
    Vec3 a, b;                     // world space
    std::uint32_t faces[2];        // the two faces that share it (scene polygon indices)
};
struct LineDrawingInput {
    std::vector<ConvexBody> bodies;
    std::vector<BodyEdge> edges;
};

// The scene's polygons grouped into bodies by shared edges, each body's edges once. InvalidInput names the polygon
// of a body that is not closed (an edge with one face), not convex (a vertex outside a face's plane), or reaches
// behind the eye (Roberts' transform needs it in front).
LineDrawingInput convex_bodies(const Scene& scene);

struct RobertsOptions {
    std::uint64_t max_tests = std::uint64_t(1) << 32;  // edge-against-body tests before it stops (step bound)
};

struct DrawnEdge {
    std::vector<std::pair<double, double>> hidden;   // merged, sorted parts [t0, t1] of the edge hidden
    bool removed = false;                            // both faces face away
};
struct LineDrawing {
    LineDrawingInput input;
    std::vector<DrawnEdge> edges;  // per input edge
    std::uint64_t tests = 0;
    bool bounded = false;
};

// The scene is copied into the machine: a coroutine outlives the caller's references.
Steps<RobertsEvent, LineDrawing> roberts(Scene scene, RobertsOptions options = {});

// The part [t0, t1] of the segment a→b that the convex body hides from the camera's eye (orthographic: from the
// view direction), by Roberts' linear test after the perspective transform; nothing when it hides no part.
std::optional<std::pair<double, double>> hidden_part(const Camera& camera, const ConvexBody& body, const Scene& scene, Vec3 a, Vec3 b);

}  // namespace hsr::algo
