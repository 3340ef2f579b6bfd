// SPDX-License-Identifier: MIT
// The floating horizon's curves in one colour each, the nearest green and the farthest violet: the screen's canvas
// and the 3D terrain draw a curve in the same colour, so that a student matches them across the two views.
#pragma once

#include "scene/scene.h"

namespace hsr::viz {

inline algo::Color horizon_curve_colour(int row, int rows) {
    const double t = rows > 1 ? double(row) / double(rows - 1) : 0.0;
    return {std::uint8_t(110 + 90 * t), std::uint8_t(215 - 120 * t), std::uint8_t(120 + 120 * t)};
}

}  // namespace hsr::viz
