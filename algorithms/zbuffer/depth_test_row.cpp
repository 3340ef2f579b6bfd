// SPDX-License-Identifier: MIT
#include "zbuffer/depth_test_row.h"

namespace hsr::algo {

std::uint64_t depth_test_row_by_pixel(std::uint32_t* depth, std::int32_t* owner, int begin, int end, double z, double per_x,
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

std::uint64_t depth_test_row(std::uint32_t* depth, std::int32_t* owner, int begin, int end, double z, double per_x, std::int32_t index,
                             const ZBufferOptions& o, double levels) {
    if (levels > 0)
        if (const auto won = integer_row_wide(depth, owner, begin, end, z, per_x, index, levels)) return *won;
    return depth_test_row_by_pixel(depth, owner, begin, end, z, per_x, index, o, levels);
}

}  // namespace hsr::algo
