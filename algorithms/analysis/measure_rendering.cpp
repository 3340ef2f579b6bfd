// SPDX-License-Identifier: MIT
// Hidden surfaces against the double-precision ray cast: the z-buffer per depth format and near/far ratio, the BSP
// per splitter rule, and depth sort. The error is the share of pixels whose visible primitive differs.
#include <algorithm>
#include <chrono>
#include <cstdio>

#include "analysis/measurement.h"
#include "analysis/painters.h"
#include "raycast/ray_cast.h"
#include "scene/random_scene.h"
#include "zbuffer/classic_scanline.h"
#include "zbuffer/zbuffer_fill.h"

namespace hsr::analysis {
namespace {

double share_differing(const std::vector<algo::SceneId>& a, const std::vector<algo::SceneId>& b) {
    std::size_t differ = 0;
    for (std::size_t k = 0; k < a.size(); ++k) differ += a[k] != b[k];
    return double(differ) / double(a.size());
}

std::uint64_t count_differing(const std::vector<algo::SceneId>& a, const std::vector<algo::SceneId>& b) {
    std::uint64_t differ = 0;
    for (std::size_t k = 0; k < a.size(); ++k) differ += a[k] != b[k];
    return differ;
}

algo::Image reference(const algo::Scene& s, algo::Viewport vp) {
    return algo::ray_cast(s, {.viewport = vp, .acceleration = algo::Acceleration::grid, .detail = algo::RayDetail::ray}).run_to_end().image;
}

std::string ratio_text(double r) {
    char b[32];
    std::snprintf(b, sizeof b, "%.0e", r);
    return b;
}

}  // namespace

std::vector<Measurement> measure_zbuffer(const ReportOptions& o) {
    const algo::Viewport vp = o.quick ? algo::Viewport{80, 60} : algo::Viewport{256, 192};
    std::vector<Measurement> rows;
    plan_runs(o, 4 * 6);  // near planes × depth formats
    // The same triangles (depths 6 to 14 from the eye) with the near plane pulled towards the eye: the ratio
    // far/near grows, and the fixed-point formats lose their resolution at the back; linear24 (eye z, linearly)
    // keeps the same step at every depth, which is why the lecture's rule of thumb (f : n < 1000 for 24 bits) is
    // about the others.
    for (const double near : {1.0, 1e-2, 1e-4, 1e-6}) {
        const algo::Scene s = algo::random_triangles({.count = o.quick ? 80u : 300u, .seed = 11, .size = 2.5, .near = near, .far = 20});
        const algo::Image ref = reference(s, vp);
        const auto screen = algo::project_polygons(s, vp);
        using F = algo::DepthFormat;
        for (const F format : {F::int16, F::int24, F::int32, F::float32, F::float32_reversed, F::linear24}) {
            algo::FrameDepth f{algo::Image(0, 0), {}, {}};
            const double ms = median_ms(o, [&] {
                f = algo::zbuffer_fill(screen, algo::zbuffer_options(s, vp, format, algo::EventDetail::polygon)).run_to_end();
            });
            rows.push_back({.family = "zbuffer", .method = std::string(algo::format_id(format)),
                            .setting = "far/near " + ratio_text(20 / near) + ", " + std::to_string(s.polygons.size()) + " triangles",
                            .median_ms = ms, .error = share_differing(f.image.ids, ref.ids),
                            .error_name = "share of pixels whose visible primitive differs from the ray cast",
                            .wrong = count_differing(f.image.ids, ref.ids), .wrong_name = "pixels differing",
                            .extra = std::to_string(vp.width) + "×" + std::to_string(vp.height)});
        }
    }
    return rows;
}

std::vector<Measurement> measure_hidden_surfaces(const ReportOptions& o) {
    const algo::Viewport vp = o.quick ? algo::Viewport{80, 60} : algo::Viewport{256, 192};
    std::vector<Measurement> rows;
    plan_runs(o, 4 + 1 + 2 + 1);  // the BSP's splitter rules, depth sort, the two scan lines, the ray cast
    const algo::Scene s = algo::random_triangles({.count = o.quick ? 60u : 120u, .seed = 5, .size = 2.5});
    const algo::Image ref = reference(s, vp);
    const std::string setting = std::to_string(s.polygons.size()) + " random triangles, some piercing";
    using R = algo::SplitterRule;
    for (const auto& rule_and_name : {std::pair{R::first, "first"}, std::pair{R::balanced, "balanced"},
                                      std::pair{R::fewest_splits, "fewest-splits"}, std::pair{R::weighted, "weighted"}}) {
        const R rule = rule_and_name.first;  // (a lambda may not capture a structured binding in clang 14)
        const char* name = rule_and_name.second;
        BspPainting p{};
        const double ms = median_ms(o, [&] { p = paint_bsp(s, rule, vp); });
        rows.push_back({.family = "hsr", .method = std::string("bsp ") + name, .setting = setting, .median_ms = ms,
                        .error = share_differing(p.image.ids, ref.ids), .error_name = "share of pixels differing from the ray cast",
                        .wrong = count_differing(p.image.ids, ref.ids), .wrong_name = "pixels differing",
                        .extra = std::to_string(p.tree.splits) + " splits, " + std::to_string(p.tree.nodes.size()) + " nodes"});
    }
    DepthSortPainting d{};
    const double ms = median_ms(o, [&] { d = paint_depth_sort(s, vp); });
    rows.push_back({.family = "hsr", .method = "depth sort", .setting = setting, .median_ms = ms,
                    .error = share_differing(d.image.ids, ref.ids), .error_name = "share of pixels differing from the ray cast",
                    .wrong = count_differing(d.image.ids, ref.ids), .wrong_name = "pixels differing",
                    .extra = std::to_string(d.sorted.splits) + " splits, " + std::to_string(d.sorted.moves) + " moves" +
                             (d.sorted.bounded ? ", stopped at a bound" : "")});
    // The scan line with a one-line z-buffer, and the classic one that compares planes only where spans begin (its
    // comparisons and extra intersections counted in a run of their own, with events)
    const auto screen = algo::project_polygons(s, vp);
    algo::ScanLineOptions line = algo::scan_line_options(s, vp, algo::DepthFormat::int24);
    line.tell_crossings = false;
    algo::FrameDepth f{algo::Image(0, 0), {}, {}};
    const double hybrid_ms = median_ms(o, [&] { f = algo::scan_line(screen, line).run_to_end(); });
    rows.push_back({.family = "hsr", .method = "scan line (one-line z-buffer, int24)", .setting = setting, .median_ms = hybrid_ms,
                    .error = share_differing(f.image.ids, ref.ids), .error_name = "share of pixels differing from the ray cast",
                    .wrong = count_differing(f.image.ids, ref.ids), .wrong_name = "pixels differing"});
    const double classic_ms = median_ms(o, [&] { f = algo::classic_scan_line(screen, {.line = line}).run_to_end(); });
    std::uint64_t compared = 0, extra = 0, covered = 0;
    line.tell_crossings = true;
    for (const auto& e : algo::classic_scan_line(screen, {.line = line})) {
        compared += std::holds_alternative<algo::DepthsCompared>(e);
        extra += std::holds_alternative<algo::PiercingFound>(e);
        if (const auto* span = std::get_if<algo::SpanColored>(&e)) covered += span->polygon >= 0 ? std::uint64_t(span->x_end - span->x_begin) : 0;
    }
    rows.push_back({.family = "hsr", .method = "scan line (classic: planes where spans begin)", .setting = setting, .median_ms = classic_ms,
                    .error = share_differing(f.image.ids, ref.ids), .error_name = "share of pixels differing from the ray cast",
                    .wrong = count_differing(f.image.ids, ref.ids), .wrong_name = "pixels differing",
                    .extra = std::to_string(compared) + " plane comparisons for " + std::to_string(covered) + " covered pixels, " +
                             std::to_string(extra) + " extra intersections where polygons pierce"});
    algo::Image r{0, 0};
    const double ray_ms = median_ms(o, [&] { r = reference(s, vp); });
    rows.push_back({.family = "hsr", .method = "ray cast (grid, the reference)", .setting = setting, .median_ms = ray_ms,
                    .error = 0, .error_name = "share of pixels differing from the ray cast", .wrong_name = "pixels differing"});
    return rows;
}

namespace {

double timed_median(int repeats, const std::function<void()>& f, Progress* progress) {
    std::vector<double> times;
    for (int k = 0; k < std::max(1, repeats); ++k) {
        if (progress && progress->cancel) throw MeasurementCancelled();
        const auto start = std::chrono::steady_clock::now();
        f();
        times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        if (progress) ++progress->done;
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

}  // namespace

double median_ms(int repeats, const std::function<void()>& f) { return timed_median(repeats, f, nullptr); }

double median_ms(const ReportOptions& o, const std::function<void()>& f) { return timed_median(o.repeats, f, o.progress); }

void plan_runs(const ReportOptions& o, int timed_calls) {
    if (o.progress) o.progress->planned += timed_calls * std::max(1, o.repeats);
}

float Progress::fraction() const {
    const int p = planned, d = done;
    return p <= 0 ? 0.f : std::clamp(float(d) / float(p), 0.f, 1.f);
}

// Its section of the report (analysis/measurement.h report_sections)
const ReportSection zbuffer_report{measure_zbuffer, {{"zbuffer", "Z-buffer: pixels differing from the ray cast, per depth format and far/near ratio"}}};

// Its section of the report (analysis/measurement.h report_sections)
const ReportSection hidden_surfaces_report{measure_hidden_surfaces, {{"hsr", "BSP and depth sort: pixels differing from the ray cast"}}};

}  // namespace hsr::analysis
