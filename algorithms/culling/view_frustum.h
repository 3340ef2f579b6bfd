// SPDX-License-Identifier: MIT
// The view frustum of a scene's camera as six planes whose fronts are inside: left, right, bottom, top, near, far
// (world space). For a perspective camera the four sides pass through the eye; for an orthographic one they are
// the sides of its box.
#pragma once

#include <vector>

#include "core/plane.h"
#include "scene/scene.h"

namespace hsr::algo {

std::vector<Plane> view_frustum(const Camera& camera);
Plane plane_through(const Vec3& normal, const Vec3& point);  // the normal need not be unit

}  // namespace hsr::algo
