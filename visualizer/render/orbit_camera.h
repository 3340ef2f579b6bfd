// SPDX-License-Identifier: MIT
// The viewer's camera in the 3D view (not the scene's camera): it orbits a target point; the mouse turns and zooms it.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace hsr::viz {

struct OrbitCamera {
    glm::vec3 target{0, 0, 0};  // world space
    float distance = 10;        // world units from the target
    float yaw = 0.6f;           // radians about +y
    float pitch = 0.35f;        // radians above the horizon, |pitch| < π/2

    void orbit(float dx_pixels, float dy_pixels);
    void zoom(float wheel_steps);
    glm::vec3 eye() const;
    glm::mat4 view_projection(float aspect) const;
};

}  // namespace hsr::viz
