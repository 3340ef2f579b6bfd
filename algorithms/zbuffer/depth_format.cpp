// SPDX-License-Identifier: MIT
#include "zbuffer/depth_format.h"

#include "core/numeric.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace hsr::algo {
namespace {

double levels(DepthFormat f) {  // 2^N − 1 for the integer formats
    switch (f) {
        case DepthFormat::int16: return 65535.0;
        case DepthFormat::int24:
        case DepthFormat::linear24: return 16777215.0;
        case DepthFormat::int32: return 4294967295.0;
        default: return 0;
    }
}

// 1 − d, computed directly (1 − d in floating point would lose the digits reversed-Z is there to keep).
double reversed_depth(double z, DepthRange r) { return r.near * (r.far - z) / (z * (r.far - r.near)); }

// |d′(z)|: how fast the window depth changes with eye distance.
double slope(double z, DepthRange r) { return r.far * r.near / ((r.far - r.near) * z * z); }

float ulp(float x) { return std::nextafter(x, std::numeric_limits<float>::infinity()) - x; }

}  // namespace

bool smaller_is_nearer(DepthFormat f) { return f != DepthFormat::float32_reversed; }

std::string_view to_string(DepthFormat f) {
    switch (f) {
        case DepthFormat::int16: return "16-bit integer";
        case DepthFormat::int24: return "24-bit integer";
        case DepthFormat::int32: return "32-bit integer";
        case DepthFormat::float32: return "32-bit float";
        case DepthFormat::float32_reversed: return "32-bit float, reversed-Z";
        case DepthFormat::linear24: return "24-bit linear eye z";
    }
    return "?";
}

std::string_view format_id(DepthFormat f) {
    switch (f) {
        case DepthFormat::int16: return "int16";
        case DepthFormat::int24: return "int24";
        case DepthFormat::int32: return "int32";
        case DepthFormat::float32: return "float32";
        case DepthFormat::float32_reversed: return "float32-reversed";
        case DepthFormat::linear24: return "linear24";
    }
    return "?";
}

double window_depth(double z, DepthRange r) {
    const double a = r.far / (r.far - r.near), b = r.far * r.near / (r.near - r.far);
    return a + b / z;
}

std::uint64_t code(DepthFormat f, double z, DepthRange r) {
    switch (f) {
        case DepthFormat::int16:
        case DepthFormat::int24:
        case DepthFormat::int32: return std::uint64_t(round_half_away(levels(f) * window_depth(z, r)));
        case DepthFormat::linear24: return std::uint64_t(round_half_away(levels(f) * (z - r.near) / (r.far - r.near)));
        case DepthFormat::float32: return std::bit_cast<std::uint32_t>(float(window_depth(z, r)));
        case DepthFormat::float32_reversed:  // larger is nearer: count down from the bit pattern of 1.0f
            return std::uint64_t(std::bit_cast<std::uint32_t>(1.0f)) -
                   std::bit_cast<std::uint32_t>(float(reversed_depth(z, r)));
    }
    return 0;
}

std::uint64_t code_of_window_depth(DepthFormat f, double d, DepthRange r, bool perspective) {
    d = std::clamp(d, 0.0, 1.0);
    switch (f) {
        case DepthFormat::int16:
        case DepthFormat::int24:
        case DepthFormat::int32: return std::uint64_t(round_half_away(levels(f) * d));
        case DepthFormat::linear24: {
            const double a = r.far / (r.far - r.near), b = r.far * r.near / (r.near - r.far);
            const double linear = perspective ? (b / (d - a) - r.near) / (r.far - r.near) : d;
            return std::uint64_t(round_half_away(levels(f) * std::clamp(linear, 0.0, 1.0)));
        }
        case DepthFormat::float32: return std::bit_cast<std::uint32_t>(float(d));
        case DepthFormat::float32_reversed:
            return std::uint64_t(std::bit_cast<std::uint32_t>(1.0f)) - std::bit_cast<std::uint32_t>(float(1 - d));
    }
    return 0;
}

double window_depth_levels(DepthFormat f) {
    return f == DepthFormat::int16 || f == DepthFormat::int24 || f == DepthFormat::int32 ? levels(f) : 0;
}

std::uint64_t far_code(DepthFormat f, DepthRange r) { return code_of_window_depth(f, 1.0, r, true); }

std::uint64_t codes_between(DepthFormat f, double z0, double z1, DepthRange r) {
    return code(f, z1, r) - code(f, z0, r);
}

double resolvable_step(DepthFormat f, double z, DepthRange r) {
    switch (f) {
        case DepthFormat::int16:
        case DepthFormat::int24:
        case DepthFormat::int32: return 1.0 / (levels(f) * slope(z, r));
        case DepthFormat::linear24: return (r.far - r.near) / levels(f);
        case DepthFormat::float32: return double(ulp(float(window_depth(z, r)))) / slope(z, r);
        case DepthFormat::float32_reversed: return double(ulp(float(reversed_depth(z, r)))) / slope(z, r);
    }
    return 0;
}

}  // namespace hsr::algo
