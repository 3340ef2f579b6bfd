// SPDX-License-Identifier: MIT
// The floating horizon (Wright 1973; the UBC notes' "horizon maps for terrain models"): a height field drawn as
// curves of constant z, nearest first, in image space. Two arrays hold, per screen column, the highest and the
// lowest screen y drawn so far; a point of a later curve shows only above the upper or below the lower horizon.
//
//   Upper[x] = −∞;  Lower[x] = +∞                  for every screen column x
//   for each curve, nearest first
//     for each screen column x
//       y = the curve's height at x, projected
//       if y > Upper[x] or y < Lower[x]: the point is visible
//       Upper[x] = max(Upper[x], y);  Lower[x] = min(Lower[x], y)
//     draw the curve where it was visible
//
// The view is parallel, along +z, tilted down by the elevation: screen y = height · cos + z · sin, screen x = world x.
// So the surface's section under one column is a chain of straight pieces between the curves, and the horizons are
// exactly what it covers on screen: in this view the algorithm is exact at its sample columns (tests check it
// against an exact ray cast). A point on a horizon (y equal to it) grazes the surface in front and counts as hidden.
#pragma once

#include <vector>

#include "core/steps.h"
#include "horizon/horizon_events.h"
#include "scene/scene.h"

namespace hsr::algo {

struct HorizonOptions {
    int columns = 64;  // screen columns the curves are sampled at
};

struct HorizonImage {
    int columns = 0, rows = 0;          // screen columns; curves
    std::vector<Sight> sight;           // rows × columns, row-major
    std::vector<double> y;              // screen y of every point, likewise
    std::vector<double> upper, lower;   // the horizons after the last curve, per column
    Sight at(int row, int column) const { return sight[std::size_t(row) * std::size_t(columns) + std::size_t(column)]; }
};

// The view's projection, shared by the machine, its reference and the window's drawing.
struct HorizonProjection {
    double cos_e, sin_e;  // of the elevation (exact 0 and 1 at 0° and 90°)
    explicit HorizonProjection(double elevation_degrees);
    double screen_y(double height, double z) const { return height * cos_e + z * sin_e; }
};
// The world x of a screen column's centre, and the terrain's height there on row `row` (linear between samples).
double column_x(const Terrain& t, int columns, int column);
double curve_height(const Terrain& t, int row, double x);

// At most this many points (rows × columns): the machine's step bound, reached in seconds.
inline constexpr std::size_t max_horizon_points = 20'000'000;

// InvalidInput for a terrain check_terrain refuses, fewer than 1 or more than 65536 columns, or more points than
// max_horizon_points.
Steps<HorizonEvent, HorizonImage> floating_horizon(Terrain terrain, HorizonOptions options);

}  // namespace hsr::algo
