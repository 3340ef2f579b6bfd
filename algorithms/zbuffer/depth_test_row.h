// The z-buffer's inner loop, shared by the machine's drain and the tiled fill (zbuffer_fill.cpp, binned_fill.cpp):
// a depth's code, and the depth test along one row.
#pragma once

#include <algorithm>
#include <cstdint>

#include "core/numeric.h"
#include "zbuffer/zbuffer_fill.h"

namespace hsr::algo {

// The code stored for window depth z: the integer formats inline (`levels` = window_depth_levels(format) > 0),
// the others through code_of_window_depth. The same number either way.
inline std::uint64_t depth_code(double z, const ZBufferOptions& o, double levels) {
    return levels > 0 ? round_nonnegative(levels * std::clamp(z, 0.0, 1.0)) : code_of_window_depth(o.format, z, o.range, o.perspective);
}

// Pixels [begin, end) of one row (`depth` and `owner` point at the row), the polygon's depth z at `begin` stepped by
// per_x: where it is nearer, the pixel takes its code and its index (colour and id follow from the index later).
// Returns how many pixels it won.
inline std::uint64_t depth_test_row(std::uint32_t* depth, std::int32_t* owner, int begin, int end, double z, double per_x,
                                    std::int32_t index, const ZBufferOptions& o, double levels) {
    std::uint64_t won = 0;
    for (int x = begin; x < end; ++x, z += per_x) {
        const std::uint64_t incoming = depth_code(z, o, levels);
        if (incoming >= depth[x]) continue;
        depth[x] = std::uint32_t(incoming);
        owner[x] = index;
        ++won;
    }
    return won;
}

}  // namespace hsr::algo
