// SPDX-License-Identifier: MIT
// The culling reference: a culled frame against the frame of every primitive. A pixel counts as lost when the full
// render shows a front face there and the culled one does not (a back face and a front face tied in depth on a
// silhouette are ordered by chance, not by visibility: such pixels are not losses).
#pragma once

#include <cstdint>

#include "scene/scene.h"
#include "zbuffer/zbuffer_fill.h"

namespace hsr::analysis {

std::uint64_t lost_front_pixels(const algo::Scene& s, const algo::FrameDepth& culled, const algo::FrameDepth& all);

}  // namespace hsr::analysis
