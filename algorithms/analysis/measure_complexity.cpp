// SPDX-License-Identifier: MIT
// The chapter's summary measured (the Greek notes' table: z-buffer O(Ps) ≈ O(p), BSP O(P²), depth sort O(P²), ray
// casting O(pP)). One generated scene family, random triangles whose size shrinks as their number grows so that
// P·s stays about the same ("in practice, as P increases, s decreases proportionally"); each algorithm run at rising
// P on a fixed image, then at rising p on a fixed P, until a run takes longer than the budget. Each row is one size;
// its error column is the fitted slope of log time against log size over all of its method's rows (the measured
// exponent), which the notes' exponent stands beside.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "analysis/measurement.h"
#include "analysis/painters.h"
#include "raycast/ray_cast.h"
#include "scene/random_scene.h"
#include "zbuffer/zbuffer_fill.h"

namespace hsr::analysis {

double fitted_slope(const std::vector<std::pair<double, double>>& xy) {
    if (xy.size() < 2) return 0;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const auto& [x, y] : xy) {
        const double lx = std::log10(x), ly = std::log10(std::max(y, 1e-9));
        sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
    }
    const double n = double(xy.size()), d = n * sxx - sx * sx;
    return d == 0 ? 0 : (n * sxy - sx * sy) / d;
}

namespace {

struct Algorithm {
    const char* name;
    const char* claim_P;  // the notes' complexity, and its exponent in P and in p
    double exponent_P, exponent_p;
    std::function<void(const algo::Scene&, algo::Viewport)> run;
};

// "In practice" triangles: P of them, each about 25 / P of the view's area.
algo::Scene triangles(std::size_t count) {
    return algo::random_triangles({.count = count, .seed = 13, .size = 2.5 * std::sqrt(100.0 / double(count))});
}

std::string size_text(double n) {
    char b[32];
    std::snprintf(b, sizeof b, n >= 1e4 ? "%.0e" : "%.0f", n);
    return b;
}

}  // namespace

std::vector<Measurement> measure_complexity(const ReportOptions& o) {
    const std::vector<Algorithm> algorithms = {
        {"z-buffer", "O(Ps) ≈ O(p)", 0, 1, [](const algo::Scene& s, algo::Viewport vp) {
             (void)algo::zbuffer_fill(algo::project_polygons(s, vp), algo::zbuffer_options(s, vp, algo::DepthFormat::int24, algo::EventDetail::polygon)).run_to_end();
         }},
        {"BSP (build and paint)", "O(P²)", 2, 0, [](const algo::Scene& s, algo::Viewport vp) { (void)paint_bsp(s, algo::SplitterRule::first, vp); }},
        {"depth sort", "O(P²)", 2, 0, [](const algo::Scene& s, algo::Viewport vp) { (void)paint_depth_sort(s, vp); }},
        {"ray casting (every primitive)", "O(pP)", 1, 1, [](const algo::Scene& s, algo::Viewport vp) {
             (void)algo::ray_cast(s, {.viewport = vp, .acceleration = algo::Acceleration::none, .detail = algo::RayDetail::ray}).run_to_end();
         }},
    };
    const std::vector<double> primitives = o.quick ? std::vector<double>{10, 30, 100, 300} : std::vector<double>{10, 100, 1000, 1e4, 1e5};
    const std::vector<int> sides = o.quick ? std::vector<int>{32, 64, 128} : std::vector<int>{64, 128, 256, 512, 1024};
    const algo::Viewport fixed_view = o.quick ? algo::Viewport{64, 48} : algo::Viewport{128, 96};
    const std::size_t fixed_primitives = o.quick ? 30 : 100;
    const double budget_ms = o.quick ? 40 : 3000;  // an algorithm stops growing after a run longer than this
    const int planned = int(algorithms.size() * (primitives.size() + sides.size()));
    plan_runs(o, planned);

    std::vector<Measurement> rows;
    int timed = 0;
    const auto sweep = [&](const Algorithm& a, bool against_P) {
        std::vector<std::pair<double, double>> points;
        const std::size_t first = rows.size();
        const std::vector<double> sizes = against_P ? primitives : std::vector<double>(sides.begin(), sides.end());
        const algo::Scene at_fixed_P = triangles(fixed_primitives);
        for (const double n : sizes) {
            const algo::Scene s = against_P ? triangles(std::size_t(n)) : at_fixed_P;
            const algo::Viewport vp = against_P ? fixed_view : algo::Viewport{int(n), int(n)};
            const double ms = median_ms(o, [&] { a.run(s, vp); });
            ++timed;
            const double size = against_P ? n : n * n;
            points.emplace_back(size, ms);
            rows.push_back({.family = against_P ? "complexity (P)" : "complexity (p)", .method = a.name,
                            .setting = against_P ? "P = " + size_text(n) + ", " + std::to_string(fixed_view.width) + "×" + std::to_string(fixed_view.height)
                                                 : "p = " + std::to_string(int(n)) + "², P = " + std::to_string(fixed_primitives),
                            .median_ms = ms, .size = size});
            if (ms > budget_ms) break;  // the next size would take too long
        }
        const double slope = fitted_slope(points);
        char extra[160];
        std::snprintf(extra, sizeof extra, "measured exponent %.2f over %zu sizes; the notes: %s, exponent %g in %s", slope, points.size(),
                      a.claim_P, against_P ? a.exponent_P : a.exponent_p, against_P ? "P" : "p");
        for (std::size_t k = first; k < rows.size(); ++k) {
            rows[k].error = slope;
            rows[k].error_name = std::string("measured exponent: the slope of log run time against log ") + (against_P ? "P" : "p");
            rows[k].extra = extra;
        }
    };
    for (const Algorithm& a : algorithms) sweep(a, true);
    for (const Algorithm& a : algorithms) sweep(a, false);
    if (o.progress) o.progress->done += (planned - timed) * std::max(1, o.repeats);  // the sizes over budget, skipped
    return rows;
}

// Its sections of the report (analysis/measurement.h report_sections)
const ReportSection complexity_report{measure_complexity, {{"complexity (P)", "The complexity table: run time against the primitives P (log–log)"}, {"complexity (p)", "The complexity table: run time against the pixels p (log–log)"}}};

}  // namespace hsr::analysis
