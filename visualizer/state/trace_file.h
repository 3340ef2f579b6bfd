// SPDX-License-Identifier: MIT
// A lesson's trace written to a file: what `hsrviz trace`, E's export and the no-display fallback write.
#pragma once

#include <optional>
#include <string>

namespace hsr::viz {

struct TraceOptions {
    std::string input;                     // a lesson or a scene file
    std::string out;                       // the JSON Lines file
    std::optional<std::string> algorithm;  // overrides the lesson's
};

// Runs the machine to completion, writes the trace, prints the event count and the trace hash. Exit code.
int run_trace(const TraceOptions& o);

}  // namespace hsr::viz
