// SPDX-License-Identifier: MIT
// 3D Liang–Barsky line clipping: each plane is an inequality t·p_i ≤ q_i on l(t) = p1 + t (p2 − p1), with the
// lecture's p_i, q_i; entering planes raise t_enter, leaving planes lower t_leave, and the segment is empty as
// soon as t_enter > t_leave.
#pragma once

#include "clipping/clip_types.h"
#include "core/steps.h"

namespace hsr::algo {

Steps<ClipEvent, SegmentClip> liang_barsky(ClipSegment segment, ClipOptions options = {});

}  // namespace hsr::algo
