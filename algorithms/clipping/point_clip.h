// SPDX-License-Identifier: MIT
// Point clipping ("trivial", as the lecture says): a point is kept when its outcode is 000000.
#pragma once

#include "clipping/clip_types.h"
#include "core/steps.h"

namespace hsr::algo {

Steps<ClipEvent, bool> clip_point(ClipPoint point, ClipOptions options = {});

}  // namespace hsr::algo
