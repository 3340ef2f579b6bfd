// SPDX-License-Identifier: MIT
// Occluding pairs in the report: P points in front of the eye, half of them in pairs exactly on one projector, every
// pair tested the two ways the Greek notes give: before the perspective transform (x/z and y/z per pair: four
// divisions for each of the P²/2 pairs) and after it (the divide by w once per point, then x′ and y′ compared with
// no division). Each way's decisions are checked against exact rationals (GMP) on the same eye-space numbers: a
// wrong decision must be 0.
#include <cstdio>
#include <random>

#include <gmpxx.h>

#include "analysis/measurement.h"
#include "perspective/perspective_transform.h"

namespace hsr::analysis {

namespace {

using algo::Vec3;

algo::Scene projector_points(int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1), depth(1.2, 4.5);
    algo::Scene s;
    s.camera.eye = {0, 0, 0}, s.camera.target = {0, 0, -1}, s.camera.near = 1, s.camera.far = 10;
    const auto add = [&](Vec3 p) { s.points.push_back({algo::SceneId(s.points.size() + 1), {}, glm::dvec4(p, 1)}); };
    while (int(s.points.size()) < count) {
        const double z = -depth(rng);
        const Vec3 p(unit(rng) * -z * 0.5, unit(rng) * -z * 0.5, z);
        add(p);
        add(s.points.size() % 4 == 1 ? p * 2.0 : Vec3(unit(rng), unit(rng), -depth(rng)));  // half the pairs on one projector
    }
    return s;
}

// Exactly on one projector: x_a·z_b = x_b·z_a and y_a·z_b = y_b·z_a.
bool exactly_same(Vec3 a, Vec3 b) {
    const mpq_class xa(a.x), ya(a.y), za(a.z), xb(b.x), yb(b.y), zb(b.z);
    return xa * zb == xb * za && ya * zb == yb * za;
}

}  // namespace

std::vector<Measurement> measure_perspective(const ReportOptions& o) {
    const std::vector<int> counts = o.quick ? std::vector<int>{64, 256} : std::vector<int>{64, 256, 1024};
    plan_runs(o, 2 * int(counts.size()));
    std::vector<Measurement> rows;
    for (const int p : counts) {
        const algo::Scene s = projector_points(p, 29);
        const algo::TransformResult r = algo::perspective_transform(s).run_to_end();  // eye and NDC of every point
        const double tolerance = algo::TransformOptions{}.tolerance;
        std::vector<char> before_same, after_same;
        const double before_ms = median_ms(o, [&] {
            before_same.clear();
            for (int a = 0; a < p; ++a)
                for (int b = a + 1; b < p; ++b)
                    before_same.push_back(algo::same_projector(algo::projector_ratios(r.eye[std::size_t(a)], true),
                                                               algo::projector_ratios(r.eye[std::size_t(b)], true), tolerance));
        });
        const double after_ms = median_ms(o, [&] {
            std::vector<glm::dvec2> xy(std::size_t(p), glm::dvec2(0));  // the divide once per point
            const glm::dmat4 m = algo::view_projection(s.camera);
            for (int a = 0; a < p; ++a) {
                const glm::dvec4 c = m * s.points[std::size_t(a)].p;
                xy[std::size_t(a)] = glm::dvec2(c.x / c.w, c.y / c.w);
            }
            after_same.clear();
            for (int a = 0; a < p; ++a)
                for (int b = a + 1; b < p; ++b) after_same.push_back(algo::same_projector(xy[std::size_t(a)], xy[std::size_t(b)], tolerance));
        });
        std::size_t pairs = 0;  // the index into both ways' answers (size_t: 32 bits in the browser build)
        std::uint64_t wrong_before = 0, wrong_after = 0, on_projector = 0;
        for (int a = 0; a < p; ++a)
            for (int b = a + 1; b < p; ++b, ++pairs) {
                const bool exact = exactly_same(r.eye[std::size_t(a)], r.eye[std::size_t(b)]);
                on_projector += exact;
                wrong_before += bool(before_same[pairs]) != exact;
                wrong_after += bool(after_same[pairs]) != exact;
            }
        const auto row = [&](const char* method, double ms, std::uint64_t wrong, std::uint64_t divisions) {
            char extra[200];
            std::snprintf(extra, sizeof extra, "%llu divisions for %llu pairs, %llu of them on one projector",
                          (unsigned long long)divisions, (unsigned long long)pairs, (unsigned long long)on_projector);
            rows.push_back({.family = "perspective transform", .method = method, .setting = std::to_string(p) + " points",
                            .median_ms = ms, .error = double(wrong) / double(pairs),
                            .error_name = "share of pairs decided unlike exact rationals", .wrong = wrong,
                            .wrong_name = "pairs decided wrong", .wrong_must_be_zero = true, .extra = extra});
        };
        row("occluding pairs before the transform (x/z, y/z per pair)", before_ms, wrong_before, 4 * std::uint64_t(pairs));
        row("occluding pairs after the transform (x′, y′; divide once)", after_ms, wrong_after, 3 * std::uint64_t(p));
    }
    return rows;
}

// Its section of the report (analysis/measurement.h report_sections)
const ReportSection perspective_report{measure_perspective, {{"perspective transform", "Occluding pairs: before and after the perspective transform, against GMP rationals"}}};

}  // namespace hsr::analysis
