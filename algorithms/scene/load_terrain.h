// SPDX-License-Identifier: MIT
// A scene's [terrain] (the floating horizon's height field), written out or generated:
//
//   [terrain]  spacing = [1, 1]  elevation = 30          # dx, dz in world units; the view's tilt in degrees
//   heights = [[0, 1, 2, 1], [1, 3, 1, 0], …]             # rows, the nearest first; every row as long
//   # or, instead of heights:  generate = "hills"  columns = 40  rows = 24  seed = 7
#pragma once

#include <cstdint>

#include "scene/scene.h"
#include "scene/toml_reader.h"

namespace hsr::algo {

inline constexpr double max_terrain_height = 1e300;  // beyond it a difference of two heights can overflow
inline constexpr std::size_t max_terrain_samples = 4'000'000;
// The floating horizon draws every row on each of the screen's columns (a lesson's grid: at most 256), and stops at
// 2·10^7 points (horizon/floating_horizon.h): so that every terrain the reader takes can be played, it takes at most
// this many rows (10^6 rows of 2 passed the samples' bound and then failed the machine's, without a line).
inline constexpr std::size_t max_terrain_rows = 78'125;

Terrain read_terrain(const TomlReader& r, const toml::table* t);  // t may be null: no terrain

// Rolling hills with a ridge and a valley, the same from a seed on every compiler (core/portable_random.h).
Terrain hills_terrain(int columns, int rows, std::uint32_t seed, double elevation = 30);

// InvalidInput naming what is wrong with a terrain made in code (the reader's checks, for generated ones).
void check_terrain(const Terrain& t);

}  // namespace hsr::algo
