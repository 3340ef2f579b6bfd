// A primitive's colour as its scene gives it (points, segments and polygons share one id space).
#pragma once

#include <glm/vec4.hpp>

#include "scene/scene.h"

namespace hsr::viz {

inline glm::vec4 scene_color(const algo::Scene& scene, std::int32_t id, float alpha) {
    const auto rgb = [&](const algo::Color& c) { return glm::vec4(c.r / 255.f, c.g / 255.f, c.b / 255.f, alpha); };
    for (const auto& p : scene.points)
        if (p.id == id) return rgb(p.color);
    for (const auto& s : scene.segments)
        if (s.id == id) return rgb(s.color);
    for (const auto& p : scene.polygons)
        if (p.id == id) return rgb(p.color);
    return {0.8f, 0.8f, 0.8f, alpha};
}

}  // namespace hsr::viz
