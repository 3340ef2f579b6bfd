// SPDX-License-Identifier: MIT
// The sightline test in 3D, for openings that do not reach floor to ceiling (windows, doors with lintels): a line
// through the plan's openings may still pass above or below one of them. Teller's separating planes give a
// conservative test. A plane through an edge of one opening and a corner of the other, with the two openings on its
// two sides, separates them; every line through both crosses it between them, and once, so beyond the second it
// stays on the second's side. The lines through the first opening and the current one therefore meet the next
// opening only inside every such plane: clip the next opening to them, and if nothing is left, no line passes
// (otherwise one may: the test never drops a cell a line can reach, it may keep one none can).
//
//   Through(first, current, next):  planes = separating planes of first and current, oriented towards current
//                                   next' = next clipped to the positive side of each
//                                   a sightline may pass when next' has area; next' becomes current
#pragma once

#include <vector>

#include "core/plane.h"

namespace hsr::algo {

class SolidSightlines {
public:
    // The first opening of the sequence (world space, convex); `tol` widens every clip towards keeping.
    SolidSightlines(std::vector<Vec3> first, double tol);
    // Narrows to the part of `next` the lines through the first and the current opening can reach; whether any is left.
    bool through(const std::vector<Vec3>& next);
    [[nodiscard]] const std::vector<Vec3>& current() const { return current_; }
    [[nodiscard]] std::size_t planes_used() const { return planes_; }

private:
    std::vector<Vec3> first_, current_;
    double tol_;
    std::size_t planes_ = 0;
    bool second_ = true;  // the next opening is the second of the sequence: any line joins two openings
};

// Planes through an edge of a and a corner of b, or an edge of b and a corner of a, with a wholly on the negative
// side and b wholly on the positive side (within tol): the separating planes, oriented towards b.
std::vector<Plane> separating_planes(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double tol);

}  // namespace hsr::algo
