// SPDX-License-Identifier: MIT
// Text to show beside a point of a 3D view (drawn by the panels, which own the fonts).
#pragma once

#include <string>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace hsr::viz {

struct Label {
    glm::vec3 world;
    std::string text;
    glm::vec4 color;
};

}  // namespace hsr::viz
