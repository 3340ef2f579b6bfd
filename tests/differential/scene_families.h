// SPDX-License-Identifier: MIT
// Generated scenes built to break hidden-surface algorithms, in families: each family aims at one way a renderer
// goes wrong (a short edge snapped the wrong way, an orthographic camera, a giant polygon beside small ones, …).
// Reproducible from a seed. Every polygon is convex and planar; ids run 1 … N.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace hsr::test {

struct SceneFamily {
    std::string name;
    std::string aims_at;  // what it is built to break, in a few words
    algo::Scene (*make)(std::uint32_t seed, double aspect);
};

// Every family, in a fixed order.
const std::vector<SceneFamily>& scene_families();

}  // namespace hsr::test
