// SPDX-License-Identifier: MIT
// The elevation (side view) of a run of openings along a line of the plan: stand beside the plan line and look at
// the vertical plane above it. Each opening the line crosses is a gap from its bottom to its top at the distance s
// where the line crosses it; a 3D sightline above this plan line is a line h = a + b·s of that plane, and it passes
// the run exactly when it goes through every gap. That is what lesson 26 shows: lines through a low window and then
// a high one climb too steeply to come down through the next low one.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "portals/cell_model.h"

namespace hsr::viz {

struct ElevationGap {
    std::uint32_t portal;
    double s, bottom, top;  // where the plan line crosses it, and the opening's heights there
};

struct Elevation {
    std::vector<ElevationGap> gaps;  // in the run's order
    double height = 3;               // of the rooms
    // The lines through the first `reached` gaps (all of them when every gap is passed): the steepest and the
    // shallowest, each as (a, b) for h = a + b·s. When reached < gaps.size(), they pass above or below gap `reached`.
    std::size_t reached = 0;
    std::vector<glm::dvec2> extremes;
    bool passes() const { return reached == gaps.size(); }
};

// The elevation of the portals `run` along the plan line through `point` along `direction`; none when the line
// misses one of them or the run is empty.
std::optional<Elevation> elevation_of(const algo::CellModel& model, const std::vector<std::uint32_t>& run,
                                      glm::dvec2 point, glm::dvec2 direction);

}  // namespace hsr::viz
