// SPDX-License-Identifier: MIT
#include "portals/pvs.h"

#include <algorithm>
#include <tuple>

#include "portals/sightline.h"
#include "portals/stab3d.h"

namespace hsr::algo {
namespace {

struct Build {
    const CellModel* model;
    PvsOptions options;
    Pvs pvs;
    std::uint32_t source = 0;
    std::vector<std::uint32_t> portals, path;  // the sequence under test, and the cells it passes (source first)
};

PortalEnds ends(const Portal& p) { return {p.left, p.right}; }

// Counts every cell reachable from `cell` as visible from the source: what a bound leaves untested stays in.
std::uint32_t assume_reachable_visible(Build& b, std::uint32_t cell) {
    std::vector<std::uint32_t> todo{cell};
    std::uint32_t added = 0;
    while (!todo.empty()) {
        const std::uint32_t c = todo.back();
        todo.pop_back();
        for (std::uint32_t k : b.model->cells[c].portals) {
            std::uint8_t& v = b.pvs.matrix[std::size_t(b.source) * b.pvs.cells + b.model->portals[k].to];
            if (!v) v = 1, ++added, todo.push_back(b.model->portals[k].to);
        }
    }
    return added;
}

// Stab(c, portals): the sequence is in b.portals; `lines` are the sightlines through all but its last portal, in the
// plan (exact), and `solid` the same in 3D, where openings have a bottom and a top (conservative: stab3d.h).
Steps<PvsEvent, bool> stab(Build* b, Sightlines lines, SolidSightlines solid, std::int32_t parent) {
    const Portal& last = b->model->portals[b->portals.back()];
    bool found = b->portals.size() == 1 || lines.through(ends(last));
    bool blocked_in_3d = false;
    if (found && b->portals.size() > 1) found = solid.through(last.opening), blocked_in_3d = !found;
    ++b->pvs.sightline_tests;
    {
        SightlineTested t{b->source, b->portals, found, lines.area()};
        t.blocked_in_3d = blocked_in_3d;
        if (found || blocked_in_3d) std::tie(t.point, t.direction) = lines.example();  // a plan line through them all
        const PvsEvent tested = std::move(t);
        co_yield tested;
    }
    if (!found) co_return false;
    // Add the cell behind the last portal to the PVS and the stab tree
    const std::uint32_t cell = last.to;
    b->pvs.matrix[std::size_t(b->source) * b->pvs.cells + cell] = 1;
    auto& tree = b->pvs.trees[b->source];
    const auto node = std::int32_t(tree.size());
    tree.push_back({cell, parent, std::int32_t(b->portals.back())});
    co_yield CellReached{b->source, cell, std::uint32_t(b->portals.size()), std::uint32_t(node), parent, std::int32_t(b->portals.back())};
    // Stab on through each portal out of it, not back into a cell on the way
    b->path.push_back(cell);
    for (std::uint32_t next : b->model->cells[cell].portals) {
        if (std::find(b->path.begin(), b->path.end(), b->model->portals[next].to) != b->path.end()) continue;
        if (b->portals.size() >= b->options.max_depth || b->pvs.sightline_tests >= b->options.max_tests) {
            b->pvs.bounded = true;
            const std::uint32_t assumed = assume_reachable_visible(*b, cell);
            const std::uint64_t limit = b->portals.size() >= b->options.max_depth ? b->options.max_depth : b->options.max_tests;
            co_yield StabBoundReached{b->source, cell, limit, assumed};
            break;
        }
        b->portals.push_back(next);
        auto child = stab(b, lines, solid, node);
        for (const auto& e : child) co_yield e;
        b->portals.pop_back();
    }
    b->path.pop_back();
    co_return true;
}

}  // namespace

std::vector<std::uint32_t> Pvs::row(std::uint32_t from) const {
    std::vector<std::uint32_t> out;
    for (std::uint32_t c = 0; c < cells; ++c)
        if (visible(from, c)) out.push_back(c);
    return out;
}

Steps<PvsEvent, Pvs> build_pvs(const CellModel* model, PvsOptions options) {
    Build b{model, options, {}, 0, {}, {}};
    b.pvs.cells = std::uint32_t(model->cells.size());
    b.pvs.matrix.assign(std::size_t(b.pvs.cells) * b.pvs.cells, 0);
    b.pvs.trees.resize(b.pvs.cells);
    for (b.source = 0; b.source < b.pvs.cells; ++b.source) {
        // StabTree(c): c sees itself, then each portal out of it starts a sequence
        co_yield StabTreeStarted{b.source};
        b.pvs.matrix[std::size_t(b.source) * b.pvs.cells + b.source] = 1;
        b.pvs.trees[b.source].push_back({b.source, -1, -1});
        b.path = {b.source};
        for (std::uint32_t first : model->cells[b.source].portals) {
            b.portals = {first};
            auto child = stab(&b, Sightlines(ends(model->portals[first])), SolidSightlines(model->portals[first].opening, model->tol.epsilon), 0);
            for (const auto& e : child) co_yield e;
        }
    }
    std::uint64_t pairs = 0;
    for (std::uint8_t v : b.pvs.matrix) pairs += v;
    co_yield PvsBuilt{b.pvs.cells, pairs, b.pvs.sightline_tests};
    co_return std::move(b.pvs);
}

}  // namespace hsr::algo
