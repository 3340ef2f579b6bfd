// SPDX-License-Identifier: MIT
#include "screens/screen.h"

#include <cmath>

#include <glm/matrix.hpp>

namespace hsr::viz {

glm::vec2 ViewGeometry::to_window(const glm::dvec3& world) const {
    const glm::vec4 c = view_projection * glm::vec4(glm::vec3(world), 1);
    return {(c.x / c.w * 0.5f + 0.5f) * width, (0.5f - c.y / c.w * 0.5f) * height};
}

std::optional<glm::dvec3> ViewGeometry::on_plane_z0(float x, float y) const {
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(view_projection));
    const double nx = x / width * 2 - 1, ny = 1 - y / height * 2;
    const glm::dvec4 a = inverse * glm::dvec4(nx, ny, -1, 1), b = inverse * glm::dvec4(nx, ny, 1, 1);
    const glm::dvec3 from = glm::dvec3(a) / a.w, to = glm::dvec3(b) / b.w;
    if (std::abs(to.z - from.z) < 1e-12) return std::nullopt;
    const double t = -from.z / (to.z - from.z);
    return from + t * (to - from);
}

void frame_bounds(OrbitCamera& camera, glm::vec3 centre, float radius) {
    camera.target = centre;
    camera.distance = radius * 2.4f;
}

}  // namespace hsr::viz
