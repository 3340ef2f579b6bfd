// SPDX-License-Identifier: MIT
#include "horizon/floating_horizon.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/numeric.h"
#include "scene/load_terrain.h"

namespace hsr::algo {

// sin e is taken as cos(90° − e), so that the two are one number at 45° (std::sin and std::cos of π/4 differ in the
// last bit, and rows on one line of sight would stop tying); at 0° and 90° they are exactly 0 and 1.
HorizonProjection::HorizonProjection(double elevation_degrees) {
    const auto cos_degrees = [](double d) { return d == 90 ? 0.0 : d == 0 ? 1.0 : std::cos(d * std::numbers::pi / 180); };
    cos_e = cos_degrees(elevation_degrees);
    sin_e = cos_degrees(90 - elevation_degrees);
}

double column_x(const Terrain& t, int columns, int column) { return (column + 0.5) * t.width() / columns; }

double curve_height(const Terrain& t, int row, double x) {
    const double u = x / t.dx;
    const int i = std::clamp(int(std::floor(u)), 0, t.columns - 2);
    const double s = u - i;
    // a + s·(b − a): exact where a = b (a level row stays level, and ties between rows stay ties), and b − a cannot
    // overflow, since heights lie within ±1e300 (load_terrain.h)
    const double a = t.height(i, row), b = t.height(i + 1, row);
    return a + s * (b - a);
}

static_assert(max_terrain_rows * 256 <= max_horizon_points, "every terrain the reader takes fits a lesson's grid of 256 columns");

Steps<HorizonEvent, HorizonImage> floating_horizon(Terrain terrain, HorizonOptions options) {
    check_terrain(terrain);
    if (options.columns < 1 || options.columns > 65536) throw InvalidInput("floating horizon: the screen has 1 to 65536 columns");
    if (std::size_t(options.columns) * std::size_t(terrain.rows) > max_horizon_points)
        throw InvalidInput("floating horizon: " + std::to_string(terrain.rows) + " curves × " + std::to_string(options.columns) +
                           " columns is beyond the step bound of " + std::to_string(max_horizon_points) + " points");
    const int W = options.columns;
    const HorizonProjection view(terrain.elevation);
    HorizonImage image{.columns = W, .rows = terrain.rows};
    image.sight.reserve(std::size_t(W) * std::size_t(terrain.rows));
    image.y.reserve(image.sight.capacity());
    // Upper[x] = −∞, Lower[x] = +∞ for every column
    std::vector<double>& upper = image.upper;
    std::vector<double>& lower = image.lower;
    upper.assign(std::size_t(W), -std::numeric_limits<double>::infinity());
    lower.assign(std::size_t(W), std::numeric_limits<double>::infinity());
    std::uint64_t visible = 0, hidden = 0;
    // for each curve, nearest first
    for (int row = 0; row < terrain.rows; ++row) {
        const double z = row * terrain.dz;
        co_yield CurveStarted{row, z};
        int counts[3] = {0, 0, 0};
        for (int x = 0; x < W; ++x) {
            // y = the curve's height at x, projected
            const double wx = column_x(terrain, W, x), height = curve_height(terrain, row, wx);
            const double y = view.screen_y(height, z);
            const double up = upper[std::size_t(x)], low = lower[std::size_t(x)];
            // visible above the upper horizon, below the lower one, or hidden between them
            const Sight sight = y > up ? Sight::above : y < low ? Sight::below : Sight::hidden;
            co_yield PointTested{row, x, wx, height, y, row == 0, row == 0 ? y : up, row == 0 ? y : low, sight};
            upper[std::size_t(x)] = std::max(up, y);
            lower[std::size_t(x)] = std::min(low, y);
            ++counts[int(sight)];
            ++(sight == Sight::hidden ? hidden : visible);
            image.sight.push_back(sight);
            image.y.push_back(y);
        }
        // draw the curve where it was visible
        co_yield CurveDrawn{row, counts[0], counts[1], counts[2]};
    }
    co_yield HorizonFinished{visible, hidden};
    co_return image;
}

}  // namespace hsr::algo
