// SPDX-License-Identifier: MIT
// The clip volume of the lecture ("Frustum Culling (3)"), in its two settings, and the tests every clipping
// algorithm shares: the boundary value of a point for a plane, the outcode, and the plane–line intersection.
//
//   cube:         the canonical view volume of an orthographic projection, -1 ≤ x, y, z ≤ 1
//   homogeneous:  clip space before the divide by w, -w ≤ x, y, z ≤ w, and w ≥ ε so that points at or
//                 behind the eye never reach the divide (Blinn and Newell's "external" segments)
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include <glm/vec4.hpp>

namespace hsr::algo {

using Vec4 = glm::dvec4;  // a clip-space point (x, y, z, w); w = 1 in the cube setting

enum class ClipSpace : std::uint8_t { cube, homogeneous };

// The planes in the lecture's bit order: bit 1 is z > zmax … bit 6 is x < xmin. w_min (w < ε) is the seventh bit
// of the homogeneous setting only.
enum class ClipPlane : std::uint8_t { z_max, z_min, y_max, y_min, x_max, x_min, w_min };

inline constexpr int plane_count(ClipSpace s) { return s == ClipSpace::homogeneous ? 7 : 6; }
inline constexpr std::array<ClipPlane, 7> all_planes = {ClipPlane::z_max, ClipPlane::z_min, ClipPlane::y_max,
                                                        ClipPlane::y_min, ClipPlane::x_max, ClipPlane::x_min,
                                                        ClipPlane::w_min};

// A 6-bit outcode (7 in the homogeneous setting). Bit k of the lecture (k = 1..6) is stored at mask 1 << (6 - k),
// so the lecture's first bit is the leftmost when printed; the w bit is 1 << 6.
struct Outcode {
    std::uint8_t bits = 0;

    static constexpr std::uint8_t mask(ClipPlane p) {
        return p == ClipPlane::w_min ? std::uint8_t{1u << 6} : std::uint8_t(1u << (5 - static_cast<int>(p)));
    }
    [[nodiscard]] constexpr bool has(ClipPlane p) const { return (bits & mask(p)) != 0; }
    [[nodiscard]] constexpr bool inside() const { return bits == 0; }
    friend constexpr Outcode operator|(Outcode a, Outcode b) { return {std::uint8_t(a.bits | b.bits)}; }
    friend constexpr Outcode operator&(Outcode a, Outcode b) { return {std::uint8_t(a.bits & b.bits)}; }
    friend constexpr bool operator==(Outcode, Outcode) = default;
};

// "010010", lecture bit order; in the homogeneous setting a set w bit is appended as "+w".
std::string to_string(Outcode c);
// "x ≤ w", "w ≥ ε", "z ≥ -1", … : the inequality a point must satisfy to be inside the plane.
std::string_view plane_inequality(ClipPlane p, ClipSpace s);
// "z max", "x min", "w min": the plane's short name.
std::string_view plane_name(ClipPlane p);

// The boundary value of p for plane R: ≥ 0 inside, < 0 outside, linear along a segment. For the plane x ≤ w it is
// w − x; in the cube x ≤ 1 it is 1 − x. The lecture's equations (3) are t = bc(p1) / (bc(p1) − bc(p2)).
double boundary_value(const Vec4& p, ClipPlane r, ClipSpace s);

// mkcode(p) of the pseudocode.
Outcode outcode(const Vec4& p, ClipSpace s);

// The parameter t along p1 → p2 at which the segment meets plane R, by the lecture's equations (3).
double intersection_parameter(double bc1, double bc2);

// The lecture's equations (3) for plane R written out as the notes print them, e.g. left:
//   t = (x1 + w1) / ((x1 − x2) + (w1 − w2)),
// with its numerator and denominator evaluated on p1, p2 (in the cube, w = 1: the planes are constants). The
// machines compute the same t as bc(p1) / (bc(p1) − bc(p2)); this is what the window shows beside it.
struct EquationThree {
    std::string_view formula;  // the right-hand side, in the notes' signs
    double numerator = 0, denominator = 0;
    [[nodiscard]] double t() const { return numerator / denominator; }
};
EquationThree equation_three(ClipPlane r, ClipSpace s, const Vec4& p1, const Vec4& p2);

// intersect_plane_line(R, p1, p2): p1 + t (p2 − p1), then snapped exactly onto R (x = w, x = −1, w = ε, …) so
// that the point tests inside R however the product rounded.
Vec4 intersect_plane_line(ClipPlane r, ClipSpace s, const Vec4& p1, const Vec4& p2, double t);

}  // namespace hsr::algo
