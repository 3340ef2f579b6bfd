// SPDX-License-Identifier: MIT
// hsrviz report: error against run time for every algorithm family (analysis/measurement.h), written as
// report.md, report.csv and one SVG chart per family into the output folder.
#pragma once

#include <string>

namespace hsr::viz {

struct ReportOptions {
    std::string out = "hsrviz-report";
    bool quick = false;  // small scenes, three repeats: a minute's check instead of the full figures
    int repeats = 5;
};

// Exit code 1 when a count that must be 0 (missed cells, lost pixels of conservative culling) is not.
int run_report(const ReportOptions& o);

}  // namespace hsr::viz
