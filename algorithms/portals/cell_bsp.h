// SPDX-License-Identifier: MIT
// Locating the viewer's cell with a BSP tree (the lecture: "uses separating planes, which may be cell boundaries,
// to recursively partition the scene; leafs represent cells"). The tree is the BSP lesson's, built over every
// cell's walls as 2D segments with the balanced splitter, so it is O(log n_c) deep for a plan of n_c cells; each
// empty leaf is then labelled with the cell its region lies in (a leaf's region never straddles a wall, since
// every wall is a splitter above it), or with none when it lies outside every cell.
#pragma once

#include <optional>

#include "bsp/bsp_tree.h"
#include "portals/cell_model.h"

namespace hsr::algo {

struct CellBsp {
    BspTree tree;
    std::vector<std::int32_t> front_cell, back_cell;  // per node: the cell of its empty front (back) leaf, −1 for none
};

CellBsp build_cell_bsp(const CellModel& model);

struct CellLocation {
    std::optional<std::uint32_t> cell;  // none: in a wall's line outside every cell, or outside the plan
    Location path;                      // the nodes from the root, and the side taken at each
};
CellLocation locate_cell(const CellBsp& bsp, Vec2 p);

}  // namespace hsr::algo
