// SPDX-License-Identifier: MIT
// The colours of the 3D view: the Okabe–Ito palette, safe for colour-blind viewers, on a dark background.
#pragma once

#include <glm/vec4.hpp>

namespace hsr::viz::palette {

inline constexpr glm::vec4 background{0.10f, 0.11f, 0.13f, 1};
inline constexpr glm::vec4 volume{0.70f, 0.72f, 0.76f, 0.9f};
inline constexpr glm::vec4 eye{0.94f, 0.89f, 0.26f, 1};           // yellow
inline constexpr glm::vec4 plane_fill{0.34f, 0.71f, 0.91f, 0.18f};  // sky blue, translucent
inline constexpr glm::vec4 plane_edge{0.34f, 0.71f, 0.91f, 1};
inline constexpr glm::vec4 working{0.95f, 0.95f, 0.95f, 1};       // the segment or polygon being cut
inline constexpr glm::vec4 inside{0.0f, 0.62f, 0.45f, 1};         // bluish green
inline constexpr glm::vec4 outside{0.84f, 0.37f, 0.0f, 1};        // vermillion
inline constexpr glm::vec4 intersection{0.90f, 0.62f, 0.0f, 1};   // orange
inline constexpr glm::vec4 parameter{0.34f, 0.71f, 0.91f, 1};
inline constexpr glm::vec4 current_edge{0.94f, 0.89f, 0.26f, 1};

}  // namespace hsr::viz::palette
