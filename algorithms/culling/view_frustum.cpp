// SPDX-License-Identifier: MIT
#include "culling/view_frustum.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace hsr::algo {

Plane plane_through(const Vec3& n, const Vec3& p) {
    const Vec3 u = glm::normalize(n);
    return {u, -glm::dot(u, p)};
}

std::vector<Plane> view_frustum(const Camera& c) {
    const Vec3 forward = glm::normalize(c.target - c.eye), right = glm::normalize(glm::cross(forward, c.up));
    const Vec3 up = glm::cross(right, forward);
    const Plane near = plane_through(forward, c.eye + c.near * forward), far = plane_through(-forward, c.eye + c.far * forward);
    if (c.projection == Projection::orthographic)
        return {plane_through(right, c.eye + c.box[0] * right), plane_through(-right, c.eye + c.box[1] * right),
                plane_through(up, c.eye + c.box[2] * up),       plane_through(-up, c.eye + c.box[3] * up), near, far};
    const double ty = std::tan(c.fov_y * M_PI / 360), tx = ty * c.aspect;
    return {plane_through(right + tx * forward, c.eye), plane_through(tx * forward - right, c.eye),
            plane_through(up + ty * forward, c.eye),    plane_through(ty * forward - up, c.eye), near, far};
}

}  // namespace hsr::algo
