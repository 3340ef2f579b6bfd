// SPDX-License-Identifier: MIT
// What the window shows beside a clipping view: the lecture's pseudocode of each clipper, with the events that
// light each line and whether they are a Step. UI policy: the machines know none of it.
#pragma once

#include "clipping/clip_events.h"
#include "clipping/clip_scene.h"
#include "state/pseudocode.h"

namespace hsr::viz {

const Pseudocode<algo::ClipEvent>& pseudocode_table(algo::ClipAlgorithm a);

}  // namespace hsr::viz
