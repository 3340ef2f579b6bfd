// SPDX-License-Identifier: MIT
// The report's files: a Markdown table per family, one CSV of every row, and a chart of error against run time per
// family (SVG: both axes logarithmic, a row with no error drawn on the "0" line at the bottom).
#pragma once

#include <string>
#include <vector>

#include "analysis/expect_check.h"
#include "analysis/measurement.h"

namespace hsr::analysis {

std::vector<std::string> families_of(const std::vector<Measurement>& rows);  // in the order they first appear
std::string report_markdown(const std::vector<Measurement>& rows);
std::string report_csv(const std::vector<Measurement>& rows);
// The catalogue of extreme cases: one section per scene file with its promise and every expectation's outcome.
struct ExtremeCase {
    std::string file, name, promise;
    std::vector<ExpectOutcome> outcomes;
    std::string load_error;  // the loader refused the file (then no outcomes)
};
std::vector<ExtremeCase> run_extreme_cases(const std::string& dir);
std::string extreme_markdown(const std::vector<ExtremeCase>& cases);
std::string error_chart_svg(const std::vector<Measurement>& rows, const std::string& family);
// A sweep's lines (rows of one family with a size): one per method, in the order they first appear, and the decades
// both log10 axes span (run time in ms against size). The SVG chart and the window's chart draw the same lines.
struct GrowthLine {
    std::string method;
    std::vector<const Measurement*> rows;  // in order of size
    std::string measured, claimed;         // the row's extra, split: "measured exponent …" and "the notes: …"
};
struct GrowthLines {
    std::vector<GrowthLine> lines;
    double x_lo = 0, x_hi = 1, y_lo = 0, y_hi = 1;  // log10 of size and of ms, whole decades
};
GrowthLines growth_lines(const std::vector<Measurement>& rows, const std::string& family);
// A sweep's chart (rows with a size): run time against size, both axes logarithmic, one line per method.
std::string growth_chart_svg(const std::vector<Measurement>& rows, const std::string& family);
// The family's chart: growth_chart_svg for a sweep, else error_chart_svg.
std::string chart_svg(const std::vector<Measurement>& rows, const std::string& family);

}  // namespace hsr::analysis
