// SPDX-License-Identifier: MIT
// The frame shown while long work runs in the window (a lesson opening on a huge scene, End on a long run): what is
// being done, how far it has come, a bar that moves while it works, and that Esc stops it.
#pragma once

#include "core/work_meter.h"

namespace hsr::viz {

void work_panel(const algo::WorkProgress& progress, float width, float height);

}  // namespace hsr::viz
