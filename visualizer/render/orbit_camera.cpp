// SPDX-License-Identifier: MIT
#include "render/orbit_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace hsr::viz {

void OrbitCamera::orbit(float dx, float dy) {
    yaw -= dx * 0.008f;
    pitch = std::clamp(pitch + dy * 0.008f, -1.5f, 1.5f);
}

void OrbitCamera::zoom(float steps) { distance = std::clamp(distance * std::pow(0.9f, steps), 0.5f, 500.0f); }

glm::vec3 OrbitCamera::eye() const {
    return target + distance * glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
}

glm::mat4 OrbitCamera::view_projection(float aspect) const {
    return glm::perspective(glm::radians(45.0f), aspect, distance * 0.01f, distance * 20.0f) *
           glm::lookAt(eye(), target, glm::vec3(0, 1, 0));
}

}  // namespace hsr::viz
