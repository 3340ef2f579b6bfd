// SPDX-License-Identifier: MIT
// A primitive's colour as its scene gives it (points, segments and polygons share one id space).
#pragma once

#include <cstdint>
#include <unordered_map>

#include <glm/vec4.hpp>

#include "scene/scene.h"

namespace hsr::viz {

// The colours of a scene's primitives by id, looked up in constant time: a view draws every primitive each frame,
// and a scan of the scene per primitive made a 65,535-triangle scene take a second a frame.
class SceneColors {
public:
    explicit SceneColors(const algo::Scene& scene) {
        rgb_.reserve(scene.points.size() + scene.segments.size() + scene.polygons.size());
        for (const auto& p : scene.points) rgb_.try_emplace(p.id, p.color);  // the first with an id wins, as before
        for (const auto& s : scene.segments) rgb_.try_emplace(s.id, s.color);
        for (const auto& p : scene.polygons) rgb_.try_emplace(p.id, p.color);
    }
    glm::vec4 operator()(std::int32_t id, float alpha) const {
        const auto c = rgb_.find(id);
        if (c == rgb_.end()) return {0.8f, 0.8f, 0.8f, alpha};
        return {c->second.r / 255.f, c->second.g / 255.f, c->second.b / 255.f, alpha};
    }

private:
    std::unordered_map<std::int32_t, algo::Color> rgb_;
};

}  // namespace hsr::viz
