// SPDX-License-Identifier: MIT
// The floating horizon's rows of the report: one terrain drawn at screen resolutions from coarse to fine. Its error
// is the image-precision error of drawing at that many columns: the share of the curves' length drawn with the wrong
// visibility, against a fine sampling (8192 columns) of the reference walk. Its wrong count compares every point
// with the exact (GMP) walk at the same columns, ties and near-ties aside; it must be 0.
#include <cmath>
#include <string>

#include "analysis/exact_horizon.h"
#include "analysis/measurement.h"
#include "horizon/floating_horizon.h"
#include "scene/load_terrain.h"

namespace hsr::analysis {

namespace {

constexpr int fine_columns = 8192;

// Of all fine samples of all curves, the share whose visibility the image at `columns` columns gets wrong (a fine
// sample takes the verdict of the coarse column it lies in).
double misdrawn_share(const algo::HorizonImage& image, const HorizonReference& fine) {
    std::uint64_t wrong = 0;
    for (int row = 0; row < fine.rows; ++row)
        for (int c = 0; c < fine.columns; ++c) {
            const int coarse = int(std::int64_t(c) * image.columns / fine.columns);
            if ((image.at(row, coarse) != algo::Sight::hidden) != fine.at(row, c)) ++wrong;
        }
    return double(wrong) / double(std::uint64_t(fine.rows) * std::uint64_t(fine.columns));
}

// Points where the machine and the exact walk disagree, other than within `tie` screen units of deciding otherwise.
std::uint64_t disagreements(const algo::HorizonImage& image, const HorizonReference& exact, double tie) {
    std::uint64_t n = 0;
    for (int row = 0; row < image.rows; ++row)
        for (int c = 0; c < image.columns; ++c) {
            const std::size_t k = std::size_t(row) * std::size_t(image.columns) + std::size_t(c);
            if ((image.sight[k] != algo::Sight::hidden) != exact.visible[k] && exact.margin[k] > tie) ++n;
        }
    return n;
}

}  // namespace

std::vector<Measurement> measure_horizon(const ReportOptions& o) {
    // seen low (12°), so that the near hills hide much of what lies behind them
    const algo::Terrain terrain = algo::hills_terrain(o.quick ? 48 : 128, o.quick ? 32 : 64, 3, 12);
    const std::vector<int> resolutions = o.quick ? std::vector<int>{16, 64, 256} : std::vector<int>{16, 64, 256, 1024};
    plan_runs(o, int(resolutions.size()));
    const HorizonReference fine = sampled_horizon(terrain, fine_columns);
    std::vector<Measurement> rows;
    for (const int columns : resolutions) {
        algo::HorizonImage image;
        const double ms = median_ms(o, [&] { image = algo::floating_horizon(terrain, {.columns = columns}).run_to_end(); });
        std::uint64_t visible = 0;
        for (const algo::Sight s : image.sight) visible += s != algo::Sight::hidden;
        const double tie = 1e-9 * 16;  // heights of a few units: a relative 1e-9 of the screen's span
        rows.push_back({.family = "horizon",
                        .method = "floating horizon",
                        .setting = "hills " + std::to_string(terrain.columns) + "×" + std::to_string(terrain.rows) + " from 12°, " +
                                   std::to_string(columns) + " columns",
                        .median_ms = ms,
                        .error = misdrawn_share(image, fine),
                        .error_name = "share of the curves' length drawn with the wrong visibility (against 8192 columns)",
                        .wrong = disagreements(image, exact_horizon(terrain, columns), tie),
                        .wrong_name = "points differing from the exact ray walk",
                        .wrong_must_be_zero = true,
                        .extra = std::to_string(visible) + " of " + std::to_string(image.sight.size()) + " points visible"});
    }
    return rows;
}

// Its section of the report (analysis/measurement.h report_sections)
const ReportSection horizon_report{measure_horizon, {{"horizon", "Floating horizon: the curves' length drawn wrong, per screen resolution"}}};

}  // namespace hsr::analysis
