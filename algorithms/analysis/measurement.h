// Error against run time: each algorithm family measured over named scenes and settings, in one run. Every number
// comes from running the code: the run time is the median of repeats, the error is against an exact or trusted
// reference (GMP rationals for clipping, the double-precision ray cast for hidden surfaces, sampled rays for the
// PVS, the unculled z-buffer for culling), never against the algorithm itself.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
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
};

struct ReportOptions {
    bool quick = false;  // small scenes and few repeats (the test suite's setting)
    int repeats = 5;
    std::string scenes_dir;  // assets/scenes: the shipped scenes some families run on
};

std::vector<Measurement> measure_clipping(const ReportOptions& o);
std::vector<Measurement> measure_zbuffer(const ReportOptions& o);
std::vector<Measurement> measure_hidden_surfaces(const ReportOptions& o);  // BSP per splitter rule, depth sort
std::vector<Measurement> measure_portals(const ReportOptions& o);
std::vector<Measurement> measure_culling(const ReportOptions& o);
std::vector<Measurement> measure_all(const ReportOptions& o);

// The median wall time of `repeats` calls of f, in milliseconds.
double median_ms(int repeats, const std::function<void()>& f);

}  // namespace hsr::analysis
