// SPDX-License-Identifier: MIT
// The z-buffer's inner loop, shared by the machine's drain and the tiled fill (zbuffer_fill.cpp, binned_fill.cpp):
// a depth's code, and the depth test along one row.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>

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
// Returns how many pixels it won. For the integer formats on processors with AVX2 it tests four pixels at a time
// (the same z, stepped by the same additions one after another, and the same codes; only the test and the writes
// are done four at once); otherwise it is depth_test_row_by_pixel.
std::uint64_t depth_test_row(std::uint32_t* depth, std::int32_t* owner, int begin, int end, double z, double per_x, std::int32_t index,
                             const ZBufferOptions& o, double levels);

// The integer formats' test four pixels at a time, where the processor can (depth_test_row_avx2.cpp: x86-64 with
// AVX2, chosen at run time); nullopt where it cannot (depth_test_row_portable.cpp on other processors).
std::optional<std::uint64_t> integer_row_wide(std::uint32_t* depth, std::int32_t* owner, int begin, int end, double z, double per_x,
                                              std::int32_t index, double levels);

// The loop pixel by pixel, which the test holds depth_test_row to.
std::uint64_t depth_test_row_by_pixel(std::uint32_t* depth, std::int32_t* owner, int begin, int end, double z, double per_x,
                                      std::int32_t index, const ZBufferOptions& o, double levels);

}  // namespace hsr::algo
