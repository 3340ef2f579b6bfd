// SPDX-License-Identifier: MIT
// The view frustum of a camera, as lines (the four corner rays from the eye to the far plane, the near and far
// rectangles), and the bounds of a scene and its eye.
#pragma once

#include <algorithm>
#include <array>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "raycast/ray_cast.h"
#include "render/line_batch.h"

namespace hsr::viz {

inline void draw_frustum(const algo::Camera& camera, LineBatch& out, glm::vec4 colour = {0.7f, 0.72f, 0.76f, 0.35f}) {
    const std::array<algo::Ray, 4> corners = {algo::ndc_ray(camera, -1, 1), algo::ndc_ray(camera, 1, 1),
                                              algo::ndc_ray(camera, 1, -1), algo::ndc_ray(camera, -1, -1)};
    for (std::size_t i = 0; i < 4; ++i) {
        const algo::Ray &a = corners[i], &b = corners[(i + 1) % 4];
        out.line(glm::vec3(camera.projection == algo::Projection::perspective ? camera.eye : a.origin),
                 glm::vec3(a.origin + a.direction), colour);
        out.line(glm::vec3(a.origin), glm::vec3(b.origin), colour);
        out.line(glm::vec3(a.origin + a.direction), glm::vec3(b.origin + b.direction), colour);
    }
}

// The box around a scene's polygons and its eye, as a centre and radius for the orbit camera.
inline void scene_bounds(const algo::Scene& scene, glm::vec3& centre, float& radius) {
    algo::Vec3 lo = scene.camera.eye, hi = scene.camera.eye;
    for (const auto& p : scene.polygons)
        for (const auto& q : p.vertices) lo = glm::min(lo, algo::Vec3(q)), hi = glm::max(hi, algo::Vec3(q));
    centre = glm::vec3((lo + hi) * 0.5);
    radius = std::max(0.5f, float(glm::length(hi - lo) * 0.5));
}

}  // namespace hsr::viz
