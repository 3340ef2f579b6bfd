// SPDX-License-Identifier: MIT
#include "screens/screen.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
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

namespace {
// The camera's right and up in the world (its view direction from yaw and pitch).
glm::vec3 camera_right(const OrbitCamera& c) { return {std::cos(c.yaw), 0, -std::sin(c.yaw)}; }
glm::vec3 camera_up(const OrbitCamera& c) {
    return {-std::sin(c.pitch) * std::sin(c.yaw), std::cos(c.pitch), -std::sin(c.pitch) * std::cos(c.yaw)};
}
}  // namespace

void frame_in_part(OrbitCamera& camera, glm::vec3 centre, float radius, ViewPart part) {
    radius /= std::min(part.right - part.left, part.bottom);  // the scene keeps the part's width and height
    // half the view's height at the target is 2.4 · tan(22.5°) ≈ 0.994 radii; its half-width 1.1 times that. The
    // target moves so that the centre is seen in the middle of the part: to its right when the part is at the
    // view's left, down along the camera's up when the part is at the view's top (which lifts the scene)
    const float across = 1 - (part.left + part.right), down = 1 - part.bottom;
    frame_bounds(camera, centre + camera_right(camera) * (0.994f * 1.1f * across * radius) - camera_up(camera) * (0.994f * down * radius), radius);
}

void frame_points_in_part(OrbitCamera& camera, const std::vector<glm::vec3>& points, ViewPart part) {
    if (points.empty()) return;
    // the points' extent across, up and along the picture (projected on the camera's right, up and view direction)
    const glm::vec3 right = camera_right(camera), up = camera_up(camera), along = glm::cross(up, right);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : points) {
        const glm::vec3 q(glm::dot(p, right), glm::dot(p, up), glm::dot(p, along));
        lo = glm::min(lo, q), hi = glm::max(hi, q);
    }
    const glm::vec3 mid = (lo + hi) * 0.5f, half = (hi - lo) * 0.5f;
    const glm::vec3 centre = right * mid.x + up * mid.y + along * mid.z;
    // the radius that holds them: the height as is, the width for a view 1.1 times as wide as tall; a quarter more for
    // perspective (the nearer points are drawn larger than their projection on the target's plane)
    const float least = std::min(part.right - part.left, part.bottom);
    const float width = (part.right - part.left) / least, height = part.bottom / least;
    const float radius = 1.25f * std::max({half.y / height, half.x / (1.1f * width), 0.25f});
    frame_in_part(camera, centre, radius, part);
}

void frame_left_of_side_box(OrbitCamera& camera, glm::vec3 centre, float radius, float share) {
    frame_in_part(camera, centre, radius, {0, 1 - share, 1});
}

void frame_above_foot_box(OrbitCamera& camera, glm::vec3 centre, float radius, float share) {
    frame_in_part(camera, centre, radius, {0, 1, 1 - share});
}

}  // namespace hsr::viz
