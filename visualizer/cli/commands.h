// SPDX-License-Identifier: MIT
// The headless commands of the command line (no window, no GL).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "state/trace_file.h"  // run_trace: `hsrviz trace`

namespace hsr::viz {

// --lesson-list: the shipped lessons, one line each (file, difficulty, algorithm, title); exit code.
int print_lesson_list();

// Checks lesson and scene files (state/lesson_check.h); with none, every shipped lesson and scene under `root`.
// Prints one line per file (and one per problem); exit code 1 when any file has a problem.
int run_check(std::vector<std::string> files, const std::string& root);

}  // namespace hsr::viz
