// SPDX-License-Identifier: MIT
// Depth formats, as the lectures store depth: the window depth d = a + b/z of an eye distance z in [near, far],
// with a = far / (far − near) and b = far·near / (near − far), kept as
//   int16, int24, int32  round((2^N − 1) · d)                (the lecture's (2^N − 1)·(a + b/z))
//   float32              d as a 32-bit float
//   float32_reversed     1 − d = near·(far − z) / (z·(far − near)) as a 32-bit float (reversed-Z: 1 at near, 0 at far)
//   linear24             round((2^24 − 1) · (z − near) / (far − near)): eye-space z, linearly, in 24 bits
// Convention: for every format but float32_reversed a smaller stored value is nearer; for float32_reversed a
// larger one is. code() hides that: it is an integer that grows with distance in every format, so the depth test
// is always `code(new) < code(stored)`.
#pragma once

#include <cstdint>
#include <string_view>

namespace hsr::algo {

enum class DepthFormat : std::uint8_t { int16, int24, int32, float32, float32_reversed, linear24 };

struct DepthRange {
    double near = 0.1, far = 1000;  // eye distances, world units, 0 < near < far
};

bool smaller_is_nearer(DepthFormat f);
std::string_view to_string(DepthFormat f);
std::string_view format_id(DepthFormat f);  // as the command line and lessons name it: int16, …, float32-reversed, linear24

// d = a + b/z, in [0, 1] for z in [near, far].
double window_depth(double z, DepthRange r);

// The stored value as an integer that grows with distance (the float formats by their bit patterns, which order
// like the values for non-negative floats).
std::uint64_t code(DepthFormat f, double z, DepthRange r);

// The code stored for a window depth d ∈ [0, 1] as a rasteriser interpolates it (d is affine on the screen).
// With a perspective camera d = a + b/z; with an orthographic one d is already linear in z, which linear24 uses.
std::uint64_t code_of_window_depth(DepthFormat f, double d, DepthRange r, bool perspective = true);
// 2^N − 1 for the window-depth integer formats (int16, int24, int32), whose code_of_window_depth is
// round(levels · clamp(d, 0, 1)); 0 for the others. For fills that compute that code inline, pixel by pixel.
double window_depth_levels(DepthFormat f);
// The code every depth buffer starts with: the far plane's.
std::uint64_t far_code(DepthFormat f, DepthRange r);

// How many codes lie between two eye distances: code(z1) − code(z0) for z0 ≤ z1.
std::uint64_t codes_between(DepthFormat f, double z0, double z1, DepthRange r);

// The smallest change of eye distance at z that the format can resolve, by the closed form: one code step divided
// by the rate at which the stored value changes with z (|d′(z)| = far·near / ((far − near)·z²) for the 1/z formats).
double resolvable_step(DepthFormat f, double z, DepthRange r);

}  // namespace hsr::algo
