// SPDX-License-Identifier: MIT
// The z-buffer fill for a machine drained with polygon-level events (no view waits on spans or pixels): the same
// loop, run tile by tile over the frame (bands of 64 rows up to 1024 pixels wide, each tile's polygons in their
// order) by a thread per core.
// Every pixel sees the polygons in the same order and every depth is stepped by the same additions as in
// zbuffer_fill's own loop, so the buffers and the counts per polygon are the same, bit for bit; a tile's buffers
// stay in the cache while its polygons are drawn. zbuffer_fill then yields its events from the counts.
#pragma once

#include <cstdint>
#include <vector>

#include "zbuffer/zbuffer_fill.h"

namespace hsr::algo {

struct PolygonCounts {
    std::vector<std::uint64_t> tested, written;  // per polygon
};

// Fills `out` (cleared buffers) with every polygon; false, and nothing done, when the step bound could be reached
// (the bound then needs the machine's own loop, which stops at the exact pixel).
bool binned_fill(FrameDepth& out, const std::vector<ScreenPolygon>& polygons, const ZBufferOptions& o, PolygonCounts& counts);

}  // namespace hsr::algo
