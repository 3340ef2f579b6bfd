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

// --algorithm's help: every algorithm id, those of one family together ("cohen_sutherland, liang_barsky, …; bsp_build,
// bsp_traversal; …"), read from the registry so that a new algorithm is listed by itself.
std::string algorithm_ids_by_family();

// Checks lesson and scene files (state/lesson_check.h); with none, every shipped lesson and scene under `root`.
// Prints one line per file (and one per problem); exit code 1 when any file has a problem.
int run_check(std::vector<std::string> files, const std::string& root);

// A command's exit code, made 1 when what it printed did not all reach the standard output (a full disk, a closed
// pipe, /dev/full): said on stderr, never a 0 with the output lost.
int with_stdout_checked(int code);

}  // namespace hsr::viz
