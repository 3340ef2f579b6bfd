// SPDX-License-Identifier: MIT
// Ray casting, the lecture's RayCasting, for each pixel the nearest intersection over all primitives, in double
// precision: the reference the other hidden-surface algorithms are checked against.
//
//   for each pixel p
//     nearest = none
//     for each primitive R (all of them, or those in the cells the ray walks)
//       I = intersect(ray(p), R)
//       if I is nearer than nearest: nearest = R at I
//     p sees nearest
//
// Each ray runs from the pixel centre's point on the near plane (t = 0) to its point on the far plane (t = 1), so
// what it sees is exactly what lies in the view volume. Ties at the same t go to the lower primitive index, so the
// accelerated walks give the same answer as brute force.
//   grid    3D DDA (Amanatides–Woo): start in the cell where the ray enters (the eye's, when inside), skip empty
//           cells, stop in the first cell whose exit lies beyond the nearest hit found.
// A primitive listed in several cells or leaves is tested once per ray (mailboxing), so an accelerated cast never
// tests more than brute force.
//   octree  children front to back; a node starting beyond the nearest hit is not entered.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/image.h"
#include "core/steps.h"
#include "culling/hierarchy.h"
#include "raycast/raycast_events.h"
#include "raycast/spatial.h"
#include "raster/screen_polygon.h"

namespace hsr::algo {

struct RayCastOptions {
    Viewport viewport;
    Acceleration acceleration = Acceleration::none;
    RayDetail detail = RayDetail::test;
    int grid_cells = 0;  // per axis; 0 picks from the primitive count
    OctreeOptions octree;
    std::uint64_t max_tests = std::uint64_t(1) << 40;  // step bound on primitive tests
    Color background{26, 28, 33};
};

struct RayCastResult {
    Image image;                          // colours and scene ids seen (0 for background)
    std::vector<std::int32_t> polygon;    // index of the polygon seen per pixel, −1 for none
    std::vector<double> t;                // the hit's ray parameter, 2 where nothing is hit
    std::uint64_t tests = 0;
    bool bounded = false;
};

// The primitives are the scene's polygons (3 or more vertices, world space); its camera casts the rays.
// InvalidInput names a polygon with NaN or infinite coordinates.
Steps<RayCastEvent, RayCastResult> ray_cast(Scene scene, RayCastOptions options);

// The grid ray_cast builds for a scene with grid_cells = cells (for a view that draws the cells it walks).
Grid ray_cast_grid(const Scene& scene, int cells = 0);
// The BVH a cast with Acceleration::bvh walks (axis boxes, at most 4 primitives a leaf), for the window to draw.
Hierarchy ray_cast_bvh(const Scene& scene);

// The ray through the centre of pixel (x, y): origin on the near plane, origin + direction on the far plane.
Ray pixel_ray(const Camera& camera, Viewport viewport, int x, int y);
// The same for a point of the image in normalised device coordinates (−1 … 1, y up).
Ray ndc_ray(const Camera& camera, double ndc_x, double ndc_y);

}  // namespace hsr::algo
