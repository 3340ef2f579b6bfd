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

void frame_left_of_side_box(OrbitCamera& camera, glm::vec3 centre, float radius, float share) {
    radius /= 1 - share;  // the scene keeps the width left of the box
    // half the view's height at the target is 2.4 · tan(22.5°) ≈ 0.994 radii; its half-width 1.1 times that
    const glm::vec3 right(std::cos(camera.yaw), 0, -std::sin(camera.yaw));
    frame_bounds(camera, centre + right * (0.994f * 1.1f * share * radius), radius);
}

void frame_above_foot_box(OrbitCamera& camera, glm::vec3 centre, float radius, float share) {
    radius /= 1 - share;  // the scene keeps the height above the box
    // the camera's up on the screen, in the world: moving the target down along it lifts the scene in the picture
    const glm::vec3 up(-std::sin(camera.pitch) * std::sin(camera.yaw), std::cos(camera.pitch), -std::sin(camera.pitch) * std::cos(camera.yaw));
    frame_bounds(camera, centre - up * (0.994f * share * radius), radius);
}

}  // namespace hsr::viz
