// SPDX-License-Identifier: MIT
#include "portals/cell_bsp.h"

#include <algorithm>

namespace hsr::algo {
namespace {

// Gives each empty leaf below `node` the cell its region (a convex polygon in z = 0) lies in.
void label_leaves(CellBsp& bsp, const CellModel& model, BspNodeId node, const std::vector<Vec3>& region) {
    const BspNode& n = bsp.tree.nodes[std::size_t(node)];
    const SplitParts parts = split(n.plane, region, bsp.tree.tolerance);
    for (const auto& [part, child, label] : {std::tuple{&parts.front, n.front, &bsp.front_cell},
                                             std::tuple{&parts.back, n.back, &bsp.back_cell}}) {
        if (child >= 0) {
            label_leaves(bsp, model, child, *part);
        } else if (part->size() >= 3 && measure(*part) > bsp.tree.tolerance.epsilon) {
            const auto cell = cell_at(model, Vec2(centroid(*part)));  // the mean of a convex polygon's corners is inside it
            (*label)[std::size_t(node)] = cell ? std::int32_t(*cell) : -1;
        }
    }
}

}  // namespace

CellBsp build_cell_bsp(const CellModel& model) {
    std::vector<BspInput> walls;
    double extent = 1;
    for (std::uint32_t c = 0; c < model.cells.size(); ++c) {
        const auto& o = model.cells[c].outline;
        for (std::size_t i = 0; i < o.size(); ++i) {
            const Vec2 a = o[i], b = o[(i + 1) % o.size()];
            walls.push_back({std::int32_t(walls.size() + 1), {Vec3(a, 0), Vec3(b, 0)}});
            extent = std::max({extent, std::abs(a.x), std::abs(a.y)});
        }
    }
    CellBsp bsp{build_bsp(std::move(walls), {.splitter = SplitterRule::balanced}).run_to_end(), {}, {}};
    bsp.front_cell.assign(bsp.tree.nodes.size(), -1);
    bsp.back_cell.assign(bsp.tree.nodes.size(), -1);
    const double r = 4 * extent;  // a square holding the whole plan
    if (bsp.tree.root >= 0) label_leaves(bsp, model, bsp.tree.root, {{-r, -r, 0}, {r, -r, 0}, {r, r, 0}, {-r, r, 0}});
    return bsp;
}

CellLocation locate_cell(const CellBsp& bsp, Vec2 p) {
    CellLocation where{std::nullopt, locate(bsp.tree, Vec3(p, 0))};
    if (where.path.path.empty()) return where;
    const auto last = std::size_t(where.path.path.back());
    const std::int32_t cell = where.path.sides.back() == Side::back ? bsp.back_cell[last] : bsp.front_cell[last];
    if (cell >= 0) where.cell = std::uint32_t(cell);
    return where;
}

}  // namespace hsr::algo
