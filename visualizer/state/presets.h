// SPDX-License-Identifier: MIT
// Scenes one click away from any lesson: the extreme cases of its algorithm (assets/scenes/extreme, each with the
// behaviour it promises), and a random scene of its family from a seed. The window lists them (P) and plays the one
// chosen with the lesson's algorithm.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/measurement.h"
#include "registry.h"

namespace hsr::viz {

struct Preset {
    std::string name;     // the scene's name ("Segment on a corner")
    std::string file;     // its path
    std::string promise;  // what it is there to show
};

// The extreme cases in `dir` that speak to the algorithm: those whose [expect] tables its family answers (clip
// expectations for the clippers, images or refusals naming it for the renderers, the PVS for portals, …). By name.
std::vector<Preset> extreme_presets(const algo::AlgorithmInfo& algorithm, const std::string& dir);

// A random scene for the algorithm's family as TOML: triangles for the renderers, 2D segments for a 2D BSP lesson,
// segments and triangles around the view volume for clipping, a maze for portals, a city for culling. nullopt for a
// family with none (z-merge).
bool has_random_scene(const algo::AlgorithmInfo& algorithm);
std::optional<std::string> random_scene_toml(const algo::AlgorithmInfo& algorithm, bool two_d, std::uint32_t seed);

// The report for the algorithm being played (R in the window): its family's rows of `hsrviz report`, measured now
// with the quick settings (small scenes, three repeats), so a student sees error against run time beside the steps.
// Each run is told to `progress` (the window's progress bar), which can cancel it (analysis::MeasurementCancelled).
std::vector<analysis::Measurement> family_report(const algo::AlgorithmInfo& algorithm, const std::string& scenes_dir,
                                                 analysis::Progress* progress = nullptr);

}  // namespace hsr::viz
