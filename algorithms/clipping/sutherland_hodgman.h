// SPDX-License-Identifier: MIT
// 3D Sutherland–Hodgman polygon clipping: a pipeline of one stage per plane of the clip volume (6, and a 7th for
// w ≥ ε in homogeneous clip space). Each stage walks the edges s → e of its input and emits by the four cases.
#pragma once

#include "clipping/clip_types.h"
#include "core/steps.h"

namespace hsr::algo {

Steps<ClipEvent, PolygonClip> sutherland_hodgman(ClipPolygon polygon, ClipOptions options = {});

}  // namespace hsr::algo
