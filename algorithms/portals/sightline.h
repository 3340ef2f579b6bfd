// SPDX-License-Identifier: MIT
// Is there a sightline through a sequence of portals? In the plan (the lecture's simplest form), a line passes
// through portals 1 … n, each in its direction, exactly when it has every portal's left end on its left and every
// right end on its right (Teller's separability condition). Lines are points (s, t) of line space, y' = s·x' + t
// in the frame of the first portal (x' across it, y' along it), and each end is a half-plane there; the sightlines
// are the convex polygon all of them leave. A sightline exists when that polygon has area: an open set of lines,
// not one grazing line along a wall. The test is exact but for lines within 0.06° of the first portal's own line
// (|s| ≤ 1000), which cannot pass through any opening of non-zero width beyond it.
#pragma once

#include <vector>

#include <glm/vec2.hpp>

namespace hsr::algo {

struct PortalEnds {
    glm::dvec2 left, right;  // plan, as seen going through
};

class Sightlines {
public:
    explicit Sightlines(const PortalEnds& first);
    // Narrows to the lines that also pass through `next`; returns whether any are left.
    bool through(const PortalEnds& next);
    [[nodiscard]] bool exist() const;
    [[nodiscard]] double area() const { return area_; }  // of the polygon in line space (s, t)
    // A sightline, in the plan: a point on it and its direction (for drawing). Only when exist().
    [[nodiscard]] std::pair<glm::dvec2, glm::dvec2> example() const;

private:
    glm::dvec2 origin_, across_, along_;  // the frame of the first portal
    double width_;                         // of the first portal: sets the scale of "no area"
    std::vector<glm::dvec2> polygon_;      // in line space (s, t)
    double area_ = 0;
    void keep(double x, double y, bool left);  // keep the lines with (x, y) on their left (or right)
};

}  // namespace hsr::algo
