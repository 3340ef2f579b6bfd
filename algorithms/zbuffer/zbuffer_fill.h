// SPDX-License-Identifier: MIT
// The z-buffer fill, as the lectures give it:
//
//   for all pixels (x, y): Depth[x, y] = far; Image[x, y] = background
//   for each polygon P
//     for each scan line y that P covers
//       [x0, x1) = the pixels of y inside P (top-left rule); z = P's depth at (x0, y)
//       for x = x0 … x1 − 1
//         if z is nearer than Depth[x, y]: Image[x, y] = colour of P; Depth[x, y] = z
//         z = z + (−a/c)                        the plane equation's forward difference
//
// The polygons come already clipped (near plane first) and projected (project_polygons). Depths are compared as
// the format stores them (depth_format.h); the test is strict, as OpenGL's GL_LESS.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/image.h"
#include "core/steps.h"
#include "zbuffer/zbuffer_events.h"

namespace hsr::algo {

struct ZBufferOptions {
    Viewport viewport;
    DepthFormat format = DepthFormat::int24;
    DepthRange range{1, 10};    // the camera's near and far
    bool perspective = true;    // how window depth relates to eye distance (for the linear format)
    EventDetail detail = EventDetail::pixel;
    std::uint64_t max_pixel_tests = std::uint64_t(1) << 36;  // step bound
    Color background{26, 28, 33};
};

// A frame buffer and its depth buffer.
struct FrameDepth {
    Image image;                       // colours and the scene id seen at each pixel (0 for background)
    std::vector<std::uint32_t> depth;  // codes, row-major, y down
    std::vector<std::int32_t> polygon; // index of the polygon seen at each pixel, −1 for background
    std::uint64_t tested = 0, written = 0;
    bool bounded = false;  // the step bound stopped the fill
};

Steps<ZBufferEvent, FrameDepth> zbuffer_fill(std::vector<ScreenPolygon> polygons, ZBufferOptions options);

// The same fill for one polygon into buffers already there, without events, for renderers that draw in batches
// and look at the buffers between them (the hierarchical z-buffer). `index` is what FrameDepth::polygon records.
// Returns the pixels written. A test holds it to the machine's answer.
std::uint64_t fill_polygon(FrameDepth& buffers, const ScreenPolygon& polygon, std::int32_t index, const ZBufferOptions& options);
// Cleared buffers: every depth at the far plane, every colour the background.
FrameDepth cleared_buffers(const ZBufferOptions& options);

// ZBufferOptions for a scene's camera (near, far, projection) and a viewport.
ZBufferOptions zbuffer_options(const Scene& scene, Viewport viewport, DepthFormat format,
                               EventDetail detail = EventDetail::pixel);

// The lecture's z-merge of two frame/depth buffer pairs of the same size and format: at each pixel the nearer
// wins (on a tie, b, as the lecture's `Za > Zb ? Fa : Fb` gives).
FrameDepth z_merge(const FrameDepth& a, const FrameDepth& b);

}  // namespace hsr::algo
