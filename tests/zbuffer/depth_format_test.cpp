// SPDX-License-Identifier: MIT
// Depth codes against their closed forms (the formulas are written out here, not taken from the code under test).
#include <cmath>

#include "catch.h"
#include "zbuffer/depth_format.h"

using namespace hsr::algo;

namespace {

// d(z) = a + b/z with a = f/(f − n), b = f·n/(n − f), written out again.
double d(double z, double n, double f) { return f / (f - n) + (f * n / (n - f)) / z; }

}  // namespace

TEST_CASE("16-bit codes over eye depths 500 to 1000 are a handful, 24-bit codes over a thousand", "[zbuffer][depth]") {
    const DepthRange r{0.1, 1000};
    const double span = d(1000, 0.1, 1000) - d(500, 0.1, 1000);  // ≈ 1.0001e-4 of the whole depth range
    const auto c16 = codes_between(DepthFormat::int16, 500, 1000, r);
    const auto c24 = codes_between(DepthFormat::int24, 500, 1000, r);
    CHECK(c16 >= 5);
    CHECK(c16 <= 8);
    CHECK(std::fabs(double(c16) - 65535.0 * span) <= 1.0);
    CHECK(c24 > 1000);
    CHECK(std::fabs(double(c24) - 16777215.0 * span) <= 1.0);
    // the other half of the distances, 0.1 to 500, holds all the rest of the codes
    CHECK(codes_between(DepthFormat::int16, 0.1, 500, r) >= 65535 - 8);
}

TEST_CASE("the smallest resolvable step at the far plane, 24 bits, near/far = 1/1000, is about 0.06",
          "[zbuffer][depth]") {
    const double n = 1, f = 1000;
    const double closed_form = f * f * (f - n) / (f * n * 16777215.0);  // z²(f − n) / (f·n·(2^24 − 1)) at z = f
    const double step = resolvable_step(DepthFormat::int24, f, {n, f});
    CHECK(step == Approx(closed_form).epsilon(1e-12));
    CHECK(step == Approx(0.0595).epsilon(0.01));
}

TEST_CASE("the step is what the codes resolve: K steps hold about K codes", "[zbuffer][depth]") {
    // The step is local (the slope of 1/z changes with z), so K steps are checked only where they span under 1%
    // of z: there the slope changes by under 2% and K = 20 steps hold 19 to 21 codes.
    int checked = 0;
    for (const DepthFormat fmt : {DepthFormat::int16, DepthFormat::int24, DepthFormat::int32, DepthFormat::linear24}) {
        INFO(to_string(fmt));
        for (const DepthRange r : {DepthRange{0.1, 100}, DepthRange{1, 1000}, DepthRange{0.01, 1e5}}) {
            for (const double z : {r.near * 3, std::sqrt(r.near * r.far), r.far * 0.6}) {
                const double step = resolvable_step(fmt, z, r);
                if (20 * step > 0.01 * z) continue;
                const auto k = codes_between(fmt, z, z + 20 * step, r);
                CHECK(k >= 19);
                CHECK(k <= 21);
                ++checked;
            }
        }
    }
    CHECK(checked >= 20);
}

TEST_CASE("codes grow with distance in every format, and reversed-Z keeps float precision far away",
          "[zbuffer][depth]") {
    for (const double ratio : {10.0, 1e3, 1e5, 1e7}) {
        const DepthRange r{1, ratio};
        for (const DepthFormat fmt : {DepthFormat::int16, DepthFormat::int24, DepthFormat::int32, DepthFormat::float32,
                                      DepthFormat::float32_reversed, DepthFormat::linear24}) {
            INFO(to_string(fmt) << ", far/near = " << ratio);
            std::uint64_t previous = code(fmt, r.near, r);
            for (int i = 1; i <= 200; ++i) {
                const double z = r.near * std::pow(r.far / r.near, i / 200.0);
                const std::uint64_t c = code(fmt, z, r);
                CHECK(c >= previous);
                previous = c;
                const double step = resolvable_step(fmt, z, r);
                CHECK(std::isfinite(step));
                CHECK(step > 0);
            }
        }
        // halfway out, reversed-Z resolves finer than a standard float (whose values crowd up near 1)
        const double z = r.far / 2;
        if (ratio >= 1e3)
            CHECK(resolvable_step(DepthFormat::float32_reversed, z, r) <
                  resolvable_step(DepthFormat::float32, z, r) / 100);
    }
    CHECK(smaller_is_nearer(DepthFormat::int24));
    CHECK_FALSE(smaller_is_nearer(DepthFormat::float32_reversed));
}
