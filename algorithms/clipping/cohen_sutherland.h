// SPDX-License-Identifier: MIT
// 3D Cohen–Sutherland line clipping with 6-bit outcodes (7 in homogeneous clip space), as the lecture's
// CS_Clip_3D: trivial accept, trivial reject, else cut at a plane where the bits differ and recurse.
#pragma once

#include "clipping/clip_types.h"
#include "core/steps.h"

namespace hsr::algo {

// Validates the input now (InvalidInput on NaN or infinity), then returns the lazy machine.
Steps<ClipEvent, SegmentClip> cohen_sutherland(ClipSegment segment, ClipOptions options = {});

}  // namespace hsr::algo
