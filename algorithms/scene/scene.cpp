// SPDX-License-Identifier: MIT
#include "scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

namespace hsr::algo {

glm::dmat4 view_projection(const Camera& c) {
    const glm::dmat4 view = glm::lookAt(c.eye, c.target, c.up);
    const glm::dmat4 projection =
        c.projection == Projection::perspective
            ? glm::perspective(glm::radians(c.fov_y), c.aspect, c.near, c.far)
            : glm::ortho(c.box[0], c.box[1], c.box[2], c.box[3], c.near, c.far);
    return projection * view;
}

glm::dvec4 to_clip(const Scene& s, const glm::dvec4& v) {
    return s.coordinates == Coordinates::clip ? v : view_projection(s.camera) * v;
}

glm::dvec3 clip_to_world(const Camera& c, const glm::dvec4& clip) {
    const glm::dvec4 w = glm::inverse(view_projection(c)) * clip;
    return glm::dvec3(w) / w.w;
}

}  // namespace hsr::algo
