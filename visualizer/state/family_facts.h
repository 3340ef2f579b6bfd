// SPDX-License-Identifier: MIT
// What the presets (P: extreme cases, a random scene) and the window's report (R) need of a family. Each session type
// has its own `static const FamilyFacts facts`, defined beside it; the helpers below are what those are made of.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "analysis/measurement.h"
#include "registry.h"
#include "scene/scene.h"

namespace hsr::viz {

struct FamilyFacts {
    // The lecture's topic the family teaches, as the lesson menu groups lessons ("Clipping", "BSP trees", …).
    std::string_view topic;
    // Whether an extreme case's [expect] tables speak to the algorithm (the family's answers are checked there).
    bool (*speaks_to)(const algo::Scene& scene, const algo::AlgorithmInfo& algorithm);
    // A random scene for the family from a seed; nullopt for a family with none. two_d: a 2D BSP lesson.
    std::optional<algo::Scene> (*random_scene)(std::uint32_t seed, bool two_d);
    // The family's rows of `hsrviz report` (R in the window measures them with the quick settings).
    std::vector<analysis::Measurement> (*measure)(const analysis::ReportOptions& options);
};

// [[expect.image]] or [[expect.rejects]] tables naming the renderer ("zbuffer", "bsp", "depth-sort", …).
bool expects_from_renderer(const algo::Scene& scene, std::string_view renderer);
// Twelve random triangles about the origin, seen by the generator's camera (every renderer's random scene).
std::optional<algo::Scene> random_triangle_scene(std::uint32_t seed, bool two_d);
// Seven random segments in the plane z = 0, seen from above (a 2D BSP lesson).
algo::Scene random_segment_scene_2d(std::uint32_t seed);
// Segments and triangles around and across a perspective camera's view volume, some behind the eye.
std::optional<algo::Scene> random_clipping_scene(std::uint32_t seed, bool two_d);
// No random scene (z-merge's two buffers come from its lesson).
std::optional<algo::Scene> no_random_scene(std::uint32_t seed, bool two_d);

}  // namespace hsr::viz
