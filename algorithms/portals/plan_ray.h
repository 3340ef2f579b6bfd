// SPDX-License-Identifier: MIT
// The reference a PVS is checked against: a ray in the floor plan from a point of a cell, followed through the
// openings it crosses until it meets a wall. Every cell it passes is visible from the start cell, so each must be
// in that cell's PVS; PVS entries no ray ever reaches are its slack.
#pragma once

#include <vector>

#include "portals/cell_model.h"

namespace hsr::algo {

// The cells the ray from p (in `cell`) along d passes through, the start cell first.
std::vector<std::uint32_t> cells_along_ray(const CellModel& model, std::uint32_t cell, Vec2 p, Vec2 d);

// The same in 3D: a ray from p (world, in `cell`, between floor and ceiling) along d, through the openings it
// crosses between their bottom and top, until it meets a wall, the floor or the ceiling.
std::vector<std::uint32_t> cells_along_ray(const CellModel& model, std::uint32_t cell, Vec3 p, Vec3 d);

}  // namespace hsr::algo
