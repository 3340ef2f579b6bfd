// SPDX-License-Identifier: MIT
// The floating horizon's reference: for every point the machine tests (a curve at a screen column), a ray from the
// point towards the eye, marched through the terrain's section under that column in exact rational arithmetic (GMP).
// The point is hidden when the ray meets the surface in front of it (touching counts: the machine counts a point
// on a horizon as hidden). It knows nothing of horizons: it walks the surface, piece by piece, from the point to the
// nearest row.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace hsr::analysis {

struct HorizonReference {
    int columns = 0, rows = 0;
    std::vector<bool> visible;  // rows × columns, row-major
    // How far each point is from deciding the other way, in screen units (0: on a tie), as a double: the distance
    // from its screen y to the nearest height the surface in front takes on the ray's line, or to its range's end.
    std::vector<double> margin;
    bool at(int row, int column) const { return visible[std::size_t(row) * std::size_t(columns) + std::size_t(column)]; }
};

// The exact answer at the machine's sample columns (the column centres and curve heights are the machine's doubles,
// taken as exact rationals; so are cos and sin of the elevation).
HorizonReference exact_horizon(const algo::Terrain& terrain, int columns);

// The same walk in double precision: fast enough for the report's fine sampling (4096 columns and more).
HorizonReference sampled_horizon(const algo::Terrain& terrain, int columns);

}  // namespace hsr::analysis
