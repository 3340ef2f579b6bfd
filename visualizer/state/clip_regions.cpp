// SPDX-License-Identifier: MIT
#include "state/clip_regions.h"

#include <cmath>

#include <glm/matrix.hpp>

namespace hsr::viz {
namespace {

using algo::ClipPlane;
using algo::Vec4;

constexpr double reach = 2.6;  // how far (in NDC x and y) the planes are drawn past the volume's ±1
constexpr double beyond = 0.35;  // how far past the far plane (and before a box's near one), as a share of its depth

// A point on the line of sight through NDC (x, y): in the slab before the near plane (−1), between the planes (0),
// or past the far plane (1).
std::optional<glm::dvec3> on_sight_line(const ClipToWorld& world, const algo::Camera& camera, double x, double y, int slab) {
    const auto n = world({x, y, -1, 1}), f = world({x, y, 1, 1});
    if (!n || !f) return std::nullopt;
    if (slab == 0) return (*n + *f) * 0.5;
    if (slab > 0) return *f + (*f - *n) * beyond;
    if (camera.projection == algo::Projection::perspective) return *n + (camera.eye - *n) * 0.5;
    return *n - (*f - *n) * beyond;
}

}  // namespace

ClipToWorld::ClipToWorld(const algo::Camera& c) : inverse_(glm::inverse(algo::view_projection(c))) {}

std::optional<glm::dvec3> ClipToWorld::operator()(const Vec4& clip) const {
    const glm::dvec4 w = inverse_ * clip;
    if (!(std::fabs(w.w) > 1e-12)) return std::nullopt;
    const glm::dvec3 p = glm::dvec3(w) / w.w;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return std::nullopt;
    return p;
}

std::vector<OutcodeRegion> outcode_regions(const algo::Camera& camera) {
    const ClipToWorld world(camera);
    std::vector<OutcodeRegion> regions;
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
            for (int k = -1; k <= 1; ++k) {
                algo::Outcode code;
                const auto set = [&](bool outside, ClipPlane r) {
                    if (outside) code.bits = std::uint8_t(code.bits | algo::Outcode::mask(r));
                };
                set(k > 0, ClipPlane::z_max), set(k < 0, ClipPlane::z_min);
                set(j > 0, ClipPlane::y_max), set(j < 0, ClipPlane::y_min);
                set(i > 0, ClipPlane::x_max), set(i < 0, ClipPlane::x_min);
                if (auto at = on_sight_line(world, camera, 2.0 * i, 2.0 * j, k)) regions.push_back({*at, code});
            }
    return regions;
}

std::vector<std::pair<glm::dvec3, glm::dvec3>> outcode_region_lines(const algo::Camera& camera) {
    const ClipToWorld world(camera);
    std::vector<std::pair<glm::dvec3, glm::dvec3>> lines;
    const auto add = [&](const std::optional<glm::dvec3>& a, const std::optional<glm::dvec3>& b) {
        if (a && b) lines.emplace_back(*a, *b);
    };
    for (int a = -1; a <= 1; a += 2)
        for (int b = -1; b <= 1; b += 2) {
            add(world({-reach, a, b, 1}), world({reach, a, b, 1}));  // y = a across the near (b = −1) or far plane
            add(world({a, -reach, b, 1}), world({a, reach, b, 1}));  // x = a across it
            const bool perspective = camera.projection == algo::Projection::perspective;
            add(perspective ? std::optional(camera.eye) : on_sight_line(world, camera, a, b, -1),
                on_sight_line(world, camera, a, b, 1));  // the side edge (x, y) = (a, b)
        }
    return lines;
}

}  // namespace hsr::viz
