// SPDX-License-Identifier: MIT
// Processors without x86's AVX2 (arm64, WebAssembly, …): no wide test, depth_test_row goes pixel by pixel.
#include "zbuffer/depth_test_row.h"

namespace hsr::algo {

std::optional<std::uint64_t> integer_row_wide(std::uint32_t*, std::int32_t*, int, int, double, double, std::int32_t, double) {
    return std::nullopt;
}

}  // namespace hsr::algo
