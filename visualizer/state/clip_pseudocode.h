// What the window shows beside a clipping view: the lecture's pseudocode, which line each event belongs to, and
// which events are a Step (major) rather than a micro-step. UI policy: the machines know none of it.
#pragma once

#include <span>
#include <string_view>

#include "clipping/clip_scene.h"

namespace hsr::viz {

std::span<const std::string_view> pseudocode(algo::ClipAlgorithm a);
// The line of pseudocode(a) that `e` belongs to.
int pseudocode_line(algo::ClipAlgorithm a, const algo::ClipEvent& e);
// A Step stops after a major event; a micro-step after any event.
bool is_major(const algo::ClipEvent& e);

}  // namespace hsr::viz
