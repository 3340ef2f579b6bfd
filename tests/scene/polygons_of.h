// SPDX-License-Identifier: MIT
// Shared by the tests: a scene's polygons as world-space vertex lists (the form the spatial structures take).
#pragma once

#include <vector>

#include "scene/scene.h"

namespace hsr::test {

inline std::vector<std::vector<algo::Vec3>> polygons_of(const algo::Scene& s) {
    std::vector<std::vector<algo::Vec3>> out;
    for (const auto& p : s.polygons) {
        std::vector<algo::Vec3> v;
        for (const auto& q : p.vertices) v.emplace_back(q);
        out.push_back(std::move(v));
    }
    return out;
}

}  // namespace hsr::test
