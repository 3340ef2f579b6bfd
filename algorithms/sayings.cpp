// SPDX-License-Identifier: MIT
#include "sayings.h"

#include "depth_sort/depth_sort_events.h"

namespace hsr::algo {

std::vector<std::span<const Saying>> machine_sayings() { return {depth_sort_sayings()}; }

}  // namespace hsr::algo
