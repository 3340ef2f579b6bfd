// SPDX-License-Identifier: MIT
// The hidden-surface renderers by the names a scene's [[expect.image]] and [[expect.rejects]] tables and
// `hsrviz render --algorithm` use: one list, read by the scene loader, the expect checks, the command line (its
// --help and its errors) and the tests. Each reader keeps its own way of running them.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <string_view>

namespace hsr::algo {

// The last, the ray cast, is the reference the others are checked against (an [[expect.image]] may not name it).
inline constexpr std::array<std::string_view, 6> renderer_names = {"zbuffer", "scanline", "scanline-classic", "bsp", "depth-sort", "raycast"};

inline bool is_renderer(std::string_view name) {
    return std::find(renderer_names.begin(), renderer_names.end(), name) != renderer_names.end();
}

// "zbuffer, scanline, …, depth-sort or raycast" (without the ray cast when `with_reference` is false).
inline std::string renderer_list(bool with_reference = true, std::string_view last_joint = " or ") {
    const std::size_t n = renderer_names.size() - (with_reference ? 0 : 1);
    std::string out;
    for (std::size_t k = 0; k < n; ++k) out += std::string(k == 0 ? "" : k + 1 == n ? last_joint : ", ") + std::string(renderer_names[k]);
    return out;
}

}  // namespace hsr::algo
