// SPDX-License-Identifier: MIT
// A vertex of the line batches: a place and a colour (no GL here: the wide-line geometry is tested without one).
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace hsr::viz {

struct ColoredVertex {
    glm::vec3 position;  // world space
    glm::vec4 color;     // straight (not premultiplied) alpha
};

}  // namespace hsr::viz
