// SPDX-License-Identifier: MIT
// What a z-buffer lesson shows: the frame and depth buffers of a classroom-sized viewport (fat pixels), the
// polygon being filled, its current span, and the pixel under test with both depths.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "zbuffer/zbuffer_fill.h"

namespace hsr::viz {

enum class PixelOutcome : std::uint8_t { none, tested, written, failed };

struct ZView {
    algo::Viewport viewport;
    algo::DepthFormat format = algo::DepthFormat::int24;
    algo::DepthRange range;
    std::shared_ptr<const std::vector<algo::ScreenPolygon>> polygons;  // never changed
    std::uint64_t far_code = 0;
    std::vector<std::int32_t> owner;   // polygon index seen per pixel, −1 background (row-major, y down)
    std::vector<std::uint64_t> depth;  // stored codes
    int polygon = -1;                  // being filled
    int span_y = -1, span_begin = 0, span_end = 0;
    int pixel_x = -1, pixel_y = -1;    // under test
    double pixel_depth = 0;            // its window depth d
    std::uint64_t incoming = 0, stored = 0;
    PixelOutcome outcome = PixelOutcome::none;
    std::uint64_t tested = 0, written = 0;
    bool done = false, bounded = false;
};

ZView initial_view(std::shared_ptr<const std::vector<algo::ScreenPolygon>> polygons, const algo::ZBufferOptions& o);
void reduce(ZView& view, const algo::ZBufferEvent& event);
std::size_t approx_bytes(const ZView& view);

}  // namespace hsr::viz
