// SPDX-License-Identifier: MIT
// References for cells and portals: what a ray cast from the eye sees (the nearest front-facing wall per pixel)
// against what portal_render drew, and how much of a PVS sampled rays from inside each cell ever reach.
#pragma once

#include <cstdint>
#include <vector>

#include "core/portable_random.h"
#include "raster/screen_polygon.h"
#include "portals/cell_model.h"
#include "portals/portal_render.h"
#include "portals/pvs.h"

namespace hsr::analysis {

struct Coverage {
    int seen = 0, missed = 0, drawn_not_seen = 0;  // polygons; missed must be 0 (conservative), the rest is slack
};
// Polygons of the model a ray cast from the model's camera sees, per pixel of vp, against r.drawn.
Coverage portal_coverage(const algo::CellModel& model, const algo::PortalRenderResult& r, algo::Viewport vp);

// A random point of the outline at least `margin` inside it.
algo::Vec2 random_point_in(const std::vector<algo::Vec2>& outline, algo::PortableRandom& rng, double margin = 1e-6);

struct PvsSampling {
    std::uint64_t pairs = 0;    // (cell, cell) pairs the PVS holds
    std::uint64_t slack = 0;    // of those, never reached by a sampled ray
    std::uint64_t missed = 0;   // cells a ray reached that the PVS leaves out: must be 0
};
// `rays` rays per cell from random points in random directions, walked through the plan's openings.
PvsSampling sample_pvs(const algo::CellModel& model, const algo::Pvs& pvs, int rays, std::uint32_t seed);

}  // namespace hsr::analysis
