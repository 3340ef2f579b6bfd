// SPDX-License-Identifier: MIT
// Random scenes for tests, benchmarks and the stability report: triangles in front of a camera, reproducible from
// a seed.
#pragma once

#include <cstdint>

#include "scene/scene.h"

namespace hsr::algo {

struct RandomTriangles {
    std::size_t count = 100;
    std::uint32_t seed = 1;
    double size = 1;            // typical edge length, world units (the scene spans about 8 × 8 × 8)
    double near = 1, far = 20;  // the camera's
};

// Triangles with ids 1 … count and random colours, centred in [−4, 4]² × [−4, 4] around the origin, seen by a
// perspective camera at (0, 0, 10) looking at the origin. Many overlap and some pierce each other.
Scene random_triangles(RandomTriangles options);

struct CellMaze {
    std::uint32_t rows = 10, cols = 10;
    std::uint32_t seed = 1;
    double extra_doors = 0.1;  // share of the walls between rooms opened beyond the maze's own (they make cycles)
};

// A floor plan of rows × cols square rooms (4 × 4 units) joined by doors 1.2 wide at random places: a maze (every
// room reachable, by a random spanning tree) plus some extra doors. Rooms are named r<row>c<col>; the eye stands in
// the first room looking across the plan.
Scene cell_maze(CellMaze options);

}  // namespace hsr::algo
