// SPDX-License-Identifier: MIT
// The A-buffer (Carpenter 1984; the UBC visibility notes: "antialiased, area-averaged accumulation buffer — z-buffer:
// one visible surface per pixel, A-buffer: linked list of surfaces; data for each surface includes RGB, Z,
// area-coverage percentage, …"). Antialiased edges and transparency in one pass:
//
//   for each polygon P:
//     for each pixel (x, y) P reaches:
//       mask = the sub-samples of (x, y) inside P      (m × m bits)
//       if mask ≠ 0: add the fragment (P's colour, opacity, depth, mask) to the list of (x, y)
//   for each pixel with a list:
//     sort the list by depth, nearest first
//     for each sub-sample s: light through s = 1, colour of s = 0
//     for each fragment f, front to back:
//       for each sub-sample s in f's mask:
//         colour of s += light through s · α_f · colour_f;  light through s ·= (1 − α_f)
//     pixel = the mean over the sub-samples (premultiplied: over nothing)
//
// A fragment keeps one depth for the whole pixel (at the centre of the sub-samples it covers): where two polygons
// pierce each other inside one pixel, the order there is the order at their centres. Carpenter's zmin/zmax blend is
// left out.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "abuffer/abuffer_events.h"
#include "core/steps.h"
#include "raster/screen_polygon.h"
#include "scene/scene.h"

namespace hsr::algo {

struct ABufferOptions {
    int mask_size = 4;  // 1 (the z-buffer's one sample per pixel), 2, 4 or 8
    std::uint64_t max_fragments = std::uint64_t(1) << 32;  // fragments made before it stops (step bound)
};

struct Fragment {
    std::uint32_t polygon;  // index into the scene's polygons
    std::uint64_t mask;
    double depth;
    glm::dvec3 colour;      // 0 … 1
    double opacity;
};

struct ABufferImage {
    Viewport viewport;
    int mask_size = 4;
    std::vector<std::vector<Fragment>> lists;  // per pixel (row-major), sorted nearest first once resolved
    std::vector<glm::dvec4> rgba;              // per pixel, premultiplied
    std::uint64_t fragments = 0;
    bool bounded = false;
    const glm::dvec4& at(int x, int y) const { return rgba[std::size_t(y) * std::size_t(viewport.width) + std::size_t(x)]; }
};

// The coverage mask of a screen polygon over pixel (x, y), m × m sub-samples, exact in the snapped sub-pixel grid.
std::uint64_t coverage_mask(const ScreenPolygon& polygon, int x, int y, int mask_size);
// Where sub-sample (i, j) of pixel (x, y) lies, in pixels.
glm::dvec2 sub_sample(int x, int y, int i, int j, int mask_size);
// A pixel's list resolved front to back (sorted here, nearest first; equal depths keep their order).
glm::dvec4 resolve(std::vector<Fragment>& list, int mask_size);

// The scene is copied into the machine: a coroutine outlives the caller's references. InvalidInput for a mask size
// other than 1, 2, 4 or 8, or a polygon that is not convex.
Steps<ABufferEvent, ABufferImage> a_buffer(Scene scene, Viewport viewport, ABufferOptions options = {});

}  // namespace hsr::algo
