// SPDX-License-Identifier: MIT
// Numbers we trust: the one place that says how input is checked and which precision an algorithm uses.
//
// - NaN or infinite input is rejected at the door (require_finite) with an error naming where it came from.
// - Clipping runs in double precision (glm::dvec4) on clip-space coordinates. The clip planes are exact there
//   (x = ±w, or x = ±1 in the canonical cube), so "inside" is the exact sign of a boundary value and needs no
//   tolerance; clipped points are snapped onto the plane they were clipped against, which is what keeps the
//   loops from spinning on rounding.
// - The plane w = ε that keeps points behind the eye out of the divide uses ε = ClipTolerance::w_epsilon, shown in
//   the window.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <glm/vec4.hpp>

namespace hsr::algo {

// Thrown when an algorithm or loader is handed input it cannot give a well-defined answer for.
class InvalidInput : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

// Throws InvalidInput("<where>.<x|y|z|w> is NaN") or "... is infinite" unless every coordinate is finite.
void require_finite(const glm::dvec4& p, const std::string& where);
void require_finite(double value, const std::string& where);
// The same with the name made only on failure: `where()` returns it (for loops over many vertices).
template <class Where>
    requires std::is_invocable_r_v<std::string, Where>
void require_finite(const glm::dvec4& p, Where&& where) {
    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w))) require_finite(p, std::string(where()));
}

// std::llround's answer (halves away from zero) without its call: x − trunc(x) is exact, so the test is too.
// The same for 0 ≤ x < 2^63, as the depth codes need it pixel by pixel: x + 0.5 is exact for x ≥ 0.5 (x and the
// sum share a binade or the sum stays below the next integer), so truncating it rounds halves up; below 0.5 the
// answer is 0 (x + 0.5 itself would round 0.49999999999999994 up to 1).
inline std::uint64_t round_nonnegative(double x) { return x < 0.5 ? 0 : static_cast<std::uint64_t>(x + 0.5); }

// Out of range (or NaN) it gives what llround gives there on x86, the least long long, without an undefined cast.
inline long long round_half_away(double x) {
    double r = std::trunc(x);
    if (std::fabs(x - r) >= 0.5) r += std::copysign(1.0, x);
    if (!(r >= -9223372036854775808.0 && r < 9223372036854775808.0)) return std::numeric_limits<long long>::min();
    return static_cast<long long>(r);
}

// ⌊a / b⌋ and ⌈a / b⌉ for b > 0 (C++'s division truncates towards zero): the rasterisers' sub-pixel arithmetic.
inline std::int64_t floor_div(std::int64_t a, std::int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
inline std::int64_t ceil_div(std::int64_t a, std::int64_t b) { return -floor_div(-a, b); }

struct ClipTolerance {
    static constexpr double w_epsilon = 1e-9;  // clip-space w below which a point counts as at or behind the eye
    // The largest clip-space coordinate a clipper takes. A boundary value (w − x) is at most twice it and the
    // difference of two (the lecture's p_i = q1 − q2) four times, so nothing a clipper computes can overflow to
    // infinity and then to NaN; 1e307 leaves room for that, where 1.5e308 did not.
    static constexpr double largest_coordinate = 1e307;
};

inline bool clippable(const glm::dvec4& p) {
    constexpr double m = ClipTolerance::largest_coordinate;
    return std::fabs(p.x) <= m && std::fabs(p.y) <= m && std::fabs(p.z) <= m && std::fabs(p.w) <= m;  // false for NaN
}
// Throws InvalidInput("<where>.<axis> is 1.5e+308, beyond ±1e+307 …") for a finite coordinate a clipper cannot take.
void require_clippable(const glm::dvec4& p, const std::string& where);

}  // namespace hsr::algo
