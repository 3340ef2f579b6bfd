// SPDX-License-Identifier: MIT
// The depth test along a row, pixel by pixel and four pixels at a time (AVX2, integer formats): the same buffers,
// the same count, for every format, span length and alignment, with depths on rounding ties and beyond [0, 1].
#include "catch.h"

#include <random>

#include "zbuffer/depth_test_row.h"

using namespace hsr::algo;

TEST_CASE("the depth test four pixels at a time writes what the pixel-by-pixel loop writes", "[zbuffer][wide]") {
    std::mt19937 rng(17);
    std::uniform_int_distribution<int> length(0, 41), start(0, 7), coin(0, 3);
    std::uniform_real_distribution<double> depth(-0.2, 1.2), slope(-0.02, 0.02);
    std::uniform_int_distribution<std::uint32_t> any_code;
    for (const DepthFormat format : {DepthFormat::int16, DepthFormat::int24, DepthFormat::int32, DepthFormat::float32, DepthFormat::linear24}) {
        INFO("format " << to_string(format));
        const ZBufferOptions o{.format = format, .range = {1, 10}};
        const double levels = window_depth_levels(format);
        std::uint64_t won = 0;
        for (int n = 0; n < 20000; ++n) {
            const int begin = start(rng), end = begin + length(rng);
            // stored codes: far, random, or the incoming row's own codes nudged by one (ties and near-ties)
            std::vector<std::uint32_t> stored(std::size_t(end) + 3);
            double z = depth(rng);
            double per_x = coin(rng) == 0 ? 0.0 : slope(rng);
            if (levels > 0 && coin(rng) == 0) {
                // rounding ties all along the row: codes then hang on the last bit of each z, which only the same
                // additions in the same order reproduce
                z = (std::floor(z * levels) + 0.5) / levels;
                per_x = double(coin(rng) + 1) / levels;
            }
            double zx = z;
            for (int x = 0; x < int(stored.size()); ++x) {
                const std::uint32_t own = x >= begin && x < end ? std::uint32_t(depth_code(zx, o, levels)) : 0;
                if (x >= begin && x < end) zx += per_x;
                const int pick = coin(rng);
                stored[std::size_t(x)] = pick == 0 ? std::uint32_t(far_code(format, o.range)) : pick == 1 ? any_code(rng) : own + std::uint32_t(coin(rng)) - 1;
            }
            std::vector<std::int32_t> owner(stored.size(), -1);
            auto d1 = stored, d2 = stored;
            auto o1 = owner, o2 = owner;
            const std::uint64_t a = depth_test_row_by_pixel(d1.data(), o1.data(), begin, end, z, per_x, 5, o, levels);
            const std::uint64_t b = depth_test_row(d2.data(), o2.data(), begin, end, z, per_x, 5, o, levels);
            INFO("row [" << begin << ", " << end << "), z " << z << ", per_x " << per_x);
            REQUIRE(a == b);
            REQUIRE(d1 == d2);
            REQUIRE(o1 == o2);
            won += a;
        }
        CHECK(won > 50000);
    }
}
