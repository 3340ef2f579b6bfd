// SPDX-License-Identifier: MIT
// Error against run time: each algorithm family measured over named scenes and settings, in one run. Every number
// comes from running the code: the run time is the median of repeats, the error is against an exact or trusted
// reference (GMP rationals for clipping, the double-precision ray cast for hidden surfaces, sampled rays for the
// PVS, the unculled z-buffer for culling), never against the algorithm itself.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hsr::analysis {

struct Measurement {
    std::string family;      // clipping, zbuffer, hsr, portals, culling
    std::string method;      // "liang_barsky machine (double)", "int16", "bsp balanced", …
    std::string setting;     // the scene or parameters it ran on
    double median_ms = 0;    // median run time of the repeats
    double error = 0;        // the family's error measure, named by error_name
    std::string error_name;
    std::uint64_t wrong = 0;  // counts that must be 0 where wrong_must_be_zero (wrong decisions, missed cells, …)
    std::string wrong_name;
    bool wrong_must_be_zero = false;
    std::string extra;        // what else the row says: splits, slack, primitives left out per stage
    double size = 0;          // a sweep's input size at this row (the complexity table's P or p); 0: no sweep
};

// How far a measurement has come, and a request to stop it: the window runs R's measurement on a thread of its own
// and draws a progress bar with a Cancel button. Counted in timed runs: a family plans its runs when it starts
// (plan_runs), each repeat inside median_ms is one done, and a cancel is seen before the next repeat starts.
struct Progress {
    std::atomic<int> planned{0};
    std::atomic<int> done{0};
    std::atomic<bool> cancel{false};
    float fraction() const;  // done / planned, in [0, 1]
};

// Thrown out of a measurement whose Progress was cancelled.
struct MeasurementCancelled : std::runtime_error {
    MeasurementCancelled() : std::runtime_error("the measurement was cancelled") {}
};

struct ReportOptions {
    bool quick = false;  // small scenes and few repeats (the test suite's setting)
    int repeats = 5;
    std::string scenes_dir;  // assets/scenes: the shipped scenes some families run on
    Progress* progress = nullptr;  // told of each run, and asked whether to go on (none: the command line's report)
};

std::vector<Measurement> measure_clipping(const ReportOptions& o);
std::vector<Measurement> measure_zbuffer(const ReportOptions& o);
std::vector<Measurement> measure_hidden_surfaces(const ReportOptions& o);  // BSP per splitter rule, depth sort
std::vector<Measurement> measure_portals(const ReportOptions& o);
std::vector<Measurement> measure_culling(const ReportOptions& o);
std::vector<Measurement> measure_horizon(const ReportOptions& o);  // the floating horizon per screen resolution
std::vector<Measurement> measure_compositing(const ReportOptions& o);  // alpha compositing per storage, against GMP
std::vector<Measurement> measure_roberts(const ReportOptions& o);  // Roberts' hidden lines per body count, against rays
std::vector<Measurement> measure_perspective(const ReportOptions& o);
std::vector<Measurement> measure_abuffer(const ReportOptions& o);  // the A-buffer per mask size, against supersampled rays
// IntersectionTest(M) per kind of bounding volume: false alarms per ray, against a test of every polygon
std::vector<Measurement> measure_intersection(const ReportOptions& o);
// The Greek notes' complexity table measured: every hidden-surface algorithm's run time against the primitives P
// (family "complexity (P)") and against the pixels p (family "complexity (p)"), each row one size, with the fitted
// log–log slope of its method beside the lecture's exponent.
std::vector<Measurement> measure_complexity(const ReportOptions& o);
// The least-squares slope of log10 y against log10 x (the measured exponent of y = c·x^k); 0 with fewer than 2 points.
double fitted_slope(const std::vector<std::pair<double, double>>& xy);  // occluding pairs before and after the transform, against GMP
// A family's part of the report: how it is measured, and the title of each section its rows make (a row's family
// name → the title; one measurement may make two, as the complexity table's P and p). Each is defined beside its
// measurement, and report_sections lists them in the report's order: the one list the command line's report and
// the section titles read (R in the window measures the lesson's family alone: its session's facts).
using MeasureFamily = std::vector<Measurement> (*)(const ReportOptions&);
struct ReportSection {
    MeasureFamily measure;
    std::vector<std::pair<std::string_view, std::string_view>> titles;
};
extern const ReportSection clipping_report, zbuffer_report, hidden_surfaces_report, portals_report, culling_report, horizon_report,
    compositing_report, roberts_report, perspective_report, abuffer_report, intersection_report, complexity_report;
std::span<const ReportSection> report_sections();
// The title of the section of rows whose family is `family` ("Other" for a family no section names: a test fails).
std::string_view section_title(std::string_view family);

// The median wall time of `repeats` calls of f, in milliseconds.
double median_ms(int repeats, const std::function<void()>& f);
// The same with the report's repeats, each run told to its Progress (MeasurementCancelled when it was cancelled).
double median_ms(const ReportOptions& o, const std::function<void()>& f);
// A family's measurement makes `timed_calls` calls of median_ms(o, …): its Progress plans that many times the repeats.
void plan_runs(const ReportOptions& o, int timed_calls);

}  // namespace hsr::analysis
