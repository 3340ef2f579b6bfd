// SPDX-License-Identifier: MIT
// The A-buffer in the report: error against run time per mask size. A scene of overlapping polygons, half of them
// translucent, each parallel to the image plane at a depth of its own (so one depth order holds in every pixel and
// the error is the sampling's alone); the reference is rays cast in world space, 16 × 16 per pixel, composited front
// to back (analysis/supersampled_rays). Mask 1 is the z-buffer's one sample per pixel: jagged edges.
#include <cmath>
#include <cstdio>
#include <random>

#include "abuffer/a_buffer.h"
#include "analysis/measurement.h"
#include "analysis/supersampled_rays.h"
#include "core/plane.h"

namespace hsr::analysis {

namespace {

algo::Scene overlapping_layers(int count, std::uint32_t seed, double aspect) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1), size(0.15, 0.9), alpha(0.3, 0.85), turn(0, 3.1);
    algo::Scene s;
    s.camera.eye = {0, 0, 6}, s.camera.target = {0, 0, 0}, s.camera.near = 1, s.camera.far = 20, s.camera.aspect = aspect;
    for (int k = 0; k < count; ++k) {
        algo::ScenePolygon p;
        p.id = algo::SceneId(k + 1);
        p.color = {std::uint8_t(rng() % 200 + 55), std::uint8_t(rng() % 200 + 55), std::uint8_t(rng() % 200 + 55)};
        p.opacity = k % 2 ? alpha(rng) : 1;
        const double r = size(rng), a0 = turn(rng);
        const algo::Vec3 c(2 * u(rng), 1.5 * u(rng), -4.0 * k / count);
        const int corners = 3 + k % 3;
        for (int v = 0; v < corners; ++v) {
            const double a = a0 + 2 * 3.14159265358979 * v / corners;
            p.vertices.emplace_back(c + algo::Vec3(r * std::cos(a), r * std::sin(a), 0), 1.0);
        }
        s.polygons.push_back(p);
    }
    return s;
}

}  // namespace

std::vector<Measurement> measure_abuffer(const ReportOptions& o) {
    const algo::Viewport vp = o.quick ? algo::Viewport{64, 48} : algo::Viewport{160, 120};
    const algo::Scene s = overlapping_layers(o.quick ? 24 : 60, 41, double(vp.width) / vp.height);
    const std::vector<glm::dvec4> reference = supersampled_image(s, vp, 16);
    const std::vector<int> masks = {1, 2, 4, 8};
    plan_runs(o, int(masks.size()));
    std::vector<Measurement> rows;
    for (const int m : masks) {
        algo::ABufferImage image;
        const double ms = median_ms(o, [&] { image = algo::a_buffer(s, vp, {.mask_size = m}).run_to_end(); });
        double sum = 0, worst = 0;
        std::size_t longest = 0, off = 0;
        for (std::size_t k = 0; k < reference.size(); ++k) {
            double e = 0;
            for (int c = 0; c < 4; ++c) e = std::max(e, std::abs(image.rgba[k][c] - reference[k][c]));
            sum += e, worst = std::max(worst, e), off += e > 2.0 / 255;
            longest = std::max(longest, image.lists[k].size());
        }
        char extra[200];
        std::snprintf(extra, sizeof extra, "%llu fragments, longest list %zu; largest error %.3g (of 1); %zu pixels",
                      (unsigned long long)image.fragments, longest, worst, reference.size());
        rows.push_back({.family = "A-buffer", .method = "A-buffer, " + std::to_string(m) + " × " + std::to_string(m) + " mask",
                        .setting = std::to_string(s.polygons.size()) + " polygons, half translucent, " + std::to_string(vp.width) + "×" +
                                   std::to_string(vp.height),
                        .median_ms = ms, .error = sum / double(reference.size()),
                        .error_name = "mean of the largest channel error per pixel against 16 × 16 rays (0 … 1)", .wrong = off,
                        .wrong_name = "pixels off by more than 2/255", .extra = extra});
    }
    return rows;
}

// Its section of the report (analysis/measurement.h report_sections)
const ReportSection abuffer_report{measure_abuffer, {{"A-buffer", "A-buffer: colour error against supersampled rays, per mask size"}}};

}  // namespace hsr::analysis
