// SPDX-License-Identifier: MIT
// Shared by the clipping tests: draining a machine, folding its events, and printing them in a failure.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "clipping/clip_events.h"
#include "core/steps.h"

namespace hsr::test {

template <class Result>
struct Drained {
    std::vector<algo::ClipEvent> events;
    Result result;
};

template <class Result>
Drained<Result> drain(algo::Steps<algo::ClipEvent, Result> machine) {
    Drained<Result> d;
    for (const auto& e : machine) d.events.push_back(e);
    d.result = machine.result();
    return d;
}

// Every event as its sentence, one per line: what a failing test prints.
inline std::string narrate(const std::vector<algo::ClipEvent>& events, algo::ClipSpace s) {
    std::string out;
    for (const auto& e : events) out += "  " + algo::describe(e, s) + "\n";
    return out;
}

// Random clip-space points: in the cube setting x, y, z in [−3, 3] and w = 1; in homogeneous clip space
// x, y, z in [−4, 4] and w in [−1, 3], so that segments cross w = 0 as well as every plane.
inline algo::Vec4 random_point(std::mt19937_64& rng, algo::ClipSpace s) {
    std::uniform_real_distribution<double> xyz(s == algo::ClipSpace::cube ? -3 : -4, s == algo::ClipSpace::cube ? 3 : 4);
    std::uniform_real_distribution<double> w(-1, 3);
    return {xyz(rng), xyz(rng), xyz(rng), s == algo::ClipSpace::cube ? 1.0 : w(rng)};
}

}  // namespace hsr::test
