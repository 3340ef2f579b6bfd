// SPDX-License-Identifier: MIT
// Random clip-space points for the clipping benchmarks: spread over the volume and beyond, some behind the eye.
#pragma once

#include <random>

#include "clipping/clip_space.h"

namespace hsr::bench {

inline algo::Vec4 random_clip_point(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> xyz(-4, 4), w(-1, 3);
    return {xyz(rng), xyz(rng), xyz(rng), w(rng)};
}

}  // namespace hsr::bench
