// SPDX-License-Identifier: MIT
#include "render/perspective_renderer.h"

#include <optional>

#include "render/palette.h"
#include "render/scene_color.h"
#include "state/strings.h"

namespace hsr::viz {

using algo::Vec3;

namespace {

constexpr int volume_edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
constexpr glm::vec4 box_colour{0.55f, 0.57f, 0.62f, 0.35f};
constexpr glm::vec4 projector_colour{0.75f, 0.77f, 0.82f, 0.35f};

// The part of a point's projector inside the view volume, in eye space: from the near plane to the far plane.
std::pair<Vec3, Vec3> projector(const PerspectiveInput& in, Vec3 p) {
    if (!in.maps.perspective) return {Vec3(p.x, p.y, -in.near), Vec3(p.x, p.y, -in.far)};
    return {p * (in.near / -p.z), p * (in.far / -p.z)};
}

}  // namespace

void draw_perspective_view(const PerspectiveView& v, const algo::Scene& scene, LineBatches& out, std::vector<Label>& labels) {
    const PerspectiveInput& in = *v.input;
    const auto at = [&](Vec3 p) { return algo::warp(in.maps, v.stage, v.s, p); };
    const SceneColors colours(scene);

    // the canonical box, where the volume is going
    for (const auto& [i, j] : volume_edges) {
        const auto corner = [](int k) { return glm::vec3(k == 1 || k == 2 || k == 5 || k == 6 ? 1 : -1, k % 4 >= 2 ? 1 : -1, k < 4 ? 1 : -1); };
        out.faint.line(corner(i), corner(j), box_colour);
    }
    // the view volume as warped so far
    for (const auto& [i, j] : volume_edges) {
        const auto a = at(in.corners[std::size_t(i)]), b = at(in.corners[std::size_t(j)]);
        if (a && b) out.bold.line(glm::vec3(*a), glm::vec3(*b), palette::volume);
    }
    // the eye, while it has a place (orthographic: none; the end of stage 2: at infinity)
    const std::optional<Vec3> eye_place = in.maps.perspective ? at(Vec3(0)) : std::nullopt;
    const bool has_eye = eye_place.has_value();
    const glm::vec3 eye = has_eye ? glm::vec3(*eye_place) : glm::vec3(0);
    if (has_eye) {
        out.bold.point(eye, palette::eye);
        labels.push_back({eye, tr("view.eye"), palette::eye});
    }

    const auto on_pair = [&](std::size_t i) { return v.pair && (v.pair->a == i || v.pair->b == i); };
    for (std::size_t i = 0; i < in.points.size(); ++i) {
        const auto p = at(in.points[i]);
        if (!p) continue;  // behind the eye: the transform has no place for it
        const auto [near_end, far_end] = projector(in, in.points[i]);
        const auto a = at(near_end), b = at(far_end);
        const bool current = on_pair(i);
        const glm::vec4 colour = v.left_out[i] ? glm::vec4(0.5f, 0.5f, 0.5f, 0.6f) : colours(scene.points[i].id, 1);
        if (a && b && !v.left_out[i]) {
            if (current) out.bold.line(glm::vec3(*a), glm::vec3(*b), v.pair->same_after ? palette::current_edge : colour);
            else out.faint.line(glm::vec3(*a), glm::vec3(*b), projector_colour);
            if (has_eye && (current || in.points.size() <= 12)) out.faint.line(eye, glm::vec3(*a), glm::vec4(projector_colour.x, projector_colour.y, projector_colour.z, 0.15f));
        }
        out.bold.point(glm::vec3(*p), current ? palette::current_edge : colour);
        labels.push_back({glm::vec3(*p), "P" + std::to_string(i), current ? palette::current_edge : colour});
    }
    // occluding pairs found: the nearer joined to the farther it occludes
    for (const auto& [nearer, farther] : v.occluding) {
        const auto a = at(in.points[nearer]), b = at(in.points[farther]);
        if (a && b) out.bold.line(glm::vec3(*a), glm::vec3(*b), palette::inside);
    }
}

}  // namespace hsr::viz
