// SPDX-License-Identifier: MIT
// The colours of the 3D view: the Okabe–Ito palette, safe for colour-blind viewers, on a dark background.
#pragma once

#include <glm/vec4.hpp>

#include "core/okabe_ito.h"

namespace hsr::viz::palette {

// An Okabe–Ito colour (core/okabe_ito.h) with an opacity, for GL.
constexpr glm::vec4 colour(algo::okabe_ito::Rgb8 c, float alpha) {
    return {algo::okabe_ito::unit(c.r), algo::okabe_ito::unit(c.g), algo::okabe_ito::unit(c.b), alpha};
}

inline constexpr glm::vec4 background{0.10f, 0.11f, 0.13f, 1};
inline constexpr glm::vec4 volume{0.70f, 0.72f, 0.76f, 0.9f};
inline constexpr glm::vec4 working{0.95f, 0.95f, 0.95f, 1};  // the segment or polygon being cut
inline constexpr glm::vec4 eye = colour(algo::okabe_ito::yellow, 1);
inline constexpr glm::vec4 current_edge = colour(algo::okabe_ito::yellow, 1);
inline constexpr glm::vec4 plane_fill = colour(algo::okabe_ito::sky_blue, 0.18f);  // translucent
inline constexpr glm::vec4 plane_edge = colour(algo::okabe_ito::sky_blue, 1);
inline constexpr glm::vec4 parameter = colour(algo::okabe_ito::sky_blue, 1);
inline constexpr glm::vec4 inside = colour(algo::okabe_ito::bluish_green, 1);
inline constexpr glm::vec4 outside = colour(algo::okabe_ito::vermillion, 1);
inline constexpr glm::vec4 intersection = colour(algo::okabe_ito::orange, 1);

}  // namespace hsr::viz::palette
