// SPDX-License-Identifier: MIT
// Pre-processing, from region (the lecture): starting from each cell c, visit the cells reachable in the cell
// adjacency graph while a sightline exists through the sequence of portals that leads there; the cells visited
// form c's stab tree, and the stab trees give the PVS matrix.
//
//   StabTree(c):                     for each portal P out of c: Stab(c, [P])
//   Stab(c, portals):                if no sightline passes through all of portals: return
//                                    (in the plan, exactly: sightline.h; in 3D, where openings have a bottom and
//                                    a top, conservatively by separating planes: stab3d.h)
//                                    add the cell behind the last portal to PVS(c)
//                                    for each portal P' out of it (not back into a cell on the way): Stab(c, portals + P')
#pragma once

#include <cstdint>
#include <vector>

#include "core/steps.h"
#include "portals/cell_model.h"
#include "portals/portal_events.h"

namespace hsr::algo {

struct StabNode {
    std::uint32_t cell;
    std::int32_t parent;  // index in the same tree; −1 for the root (the source cell)
    std::int32_t portal;  // the portal from the parent into this cell; −1 for the root
};

struct Pvs {
    std::uint32_t cells = 0;
    std::vector<std::uint8_t> matrix;         // cells × cells, row = the viewer's cell: 1 when potentially visible
    std::vector<std::vector<StabNode>> trees;  // the stab tree of each cell
    std::uint64_t sightline_tests = 0;
    bool bounded = false;                     // a bound stopped a tree; cells beyond it were counted visible
    [[nodiscard]] bool visible(std::uint32_t from, std::uint32_t to) const { return matrix[std::size_t(from) * cells + to] != 0; }
    [[nodiscard]] std::vector<std::uint32_t> row(std::uint32_t from) const;
};

struct PvsOptions {
    std::uint32_t max_depth = 256;               // portals in one sequence
    std::uint64_t max_tests = std::uint64_t(1) << 24;  // sightline tests in all
};

// The model must outlive the machine.
Steps<PvsEvent, Pvs> build_pvs(const CellModel* model, PvsOptions options = {});

}  // namespace hsr::algo
