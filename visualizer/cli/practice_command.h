// SPDX-License-Identifier: MIT
// hsrviz practice TOPIC --seed N --count K: K exercises of a topic as JSON Lines (question, choices, answer, the
// deciding event's sentence, the numbers given), for answer sheets and tests; the same seed, the same bytes.
#pragma once

#include <cstdint>
#include <string>

namespace hsr::viz {

struct PracticeOptions {
    std::string topic;           // a topic id, or "list" for the topics
    std::uint64_t seed = 1;      // the series a teacher hands out
    std::uint64_t count = 10;
    int level = 1;               // 1 easy, 2 medium, 3 hard (close to degenerate)
};

// Exit code 2 for an unknown topic (the topics are listed), 1 if an exercise could not be drawn.
int run_practice(const PracticeOptions& o);

}  // namespace hsr::viz
