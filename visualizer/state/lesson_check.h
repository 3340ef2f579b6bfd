// SPDX-License-Identifier: MIT
// `hsrviz check`: a lesson or scene file is read (schema, references: errors give file:line:column and what was
// expected), played headless to its end, and its chapters held against the machine's events (kinds that exist,
// chapters that start, questions the machine answers, answers among the choices).
#pragma once

#include <string>
#include <vector>

namespace hsr::viz {

struct CheckResult {
    std::vector<std::string> problems;  // empty: the file is good
    std::vector<std::string> warnings;  // what plays but shows wrongly: characters the window's font lacks
    std::size_t chapters = 0, questions = 0, events = 0;
};
CheckResult check_file(const std::string& path);

}  // namespace hsr::viz
