// SPDX-License-Identifier: MIT
#include "cli/practice_command.h"

#include <cstdio>
#include <exception>

#include "state/practice/practice.h"

namespace hsr::viz {

int run_practice(const PracticeOptions& o) {
    namespace p = practice;
    const p::Topic* topic = p::find_topic(o.topic);
    if (!topic) {
        if (o.topic != "list") std::fprintf(stderr, "hsrviz practice: no topic '%s'. The topics:\n", o.topic.c_str());
        for (const p::Topic& t : p::topics())
            std::fprintf(o.topic == "list" ? stdout : stderr, "  %-20s %s\n", std::string(t.id).c_str(), std::string(t.title).c_str());
        return o.topic == "list" ? 0 : 2;
    }
    try {
        for (std::uint64_t i = 0; i < o.count; ++i) {
            const std::string line = p::to_json(p::exercise(*topic, o.seed, i, p::Level(o.level))).dump();
            if (std::printf("%s\n", line.c_str()) < 0) break;  // the output is gone (main says so): no more to make
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "hsrviz practice: %s\n", e.what());
        return 1;
    }
    return 0;
}

}  // namespace hsr::viz
