// SPDX-License-Identifier: MIT
// Roberts' hidden lines in the report: k random turned boxes (k = 4 … 64), each edge against every other body, so
// the tests grow as the square of the bodies (the notes: "worse than O(n²)"). The error is the share of sampled edge
// points whose visibility differs from rays cast in world space (analysis/line_reference); it must be 0.
#include <cstdio>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "analysis/line_reference.h"
#include "analysis/measurement.h"

namespace hsr::analysis {

namespace {

algo::Scene boxes(int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-4, 4), size(0.2, 0.9), angle(0, 3.1);
    algo::Scene s;
    s.camera.eye = {0.5, 2, 14}, s.camera.target = {0, 0, 0}, s.camera.near = 1, s.camera.far = 40;
    static constexpr int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int b = 0; b < count; ++b) {
        const algo::Vec3 c(pos(rng), pos(rng), pos(rng)), h(size(rng), size(rng), size(rng));
        const glm::dmat4 turn = glm::rotate(glm::dmat4(1), angle(rng), glm::normalize(algo::Vec3(pos(rng), 3, pos(rng))));
        for (const auto& q : quads) {
            algo::ScenePolygon p;
            p.id = algo::SceneId(s.polygons.size() + 1);
            for (int k : q)
                p.vertices.emplace_back(c + algo::Vec3(turn * glm::dvec4((k & 1 ? 1 : -1) * h.x, (k & 2 ? 1 : -1) * h.y, (k & 4 ? 1 : -1) * h.z, 0)), 1.0);
            s.polygons.push_back(p);
        }
    }
    return s;
}

}  // namespace

std::vector<Measurement> measure_roberts(const ReportOptions& o) {
    const std::vector<int> counts = o.quick ? std::vector<int>{4, 8, 16} : std::vector<int>{4, 8, 16, 32, 64};
    plan_runs(o, int(counts.size()));
    std::vector<Measurement> rows;
    for (const int k : counts) {
        const algo::Scene s = boxes(k, 17);
        algo::LineDrawing d;
        const double ms = median_ms(o, [&] { d = algo::roberts(s).run_to_end(); });
        const LineAgreement a = against_rays(s, d, o.quick ? 32 : 128);
        std::size_t removed = 0;
        for (const auto& e : d.edges) removed += e.removed;
        char extra[160];
        std::snprintf(extra, sizeof extra, "%llu edge-against-body tests, %zu of %zu edges removed as back edges, %llu points undecidable",
                      (unsigned long long)d.tests, removed, d.edges.size(), (unsigned long long)a.unsure);
        rows.push_back({.family = "hidden lines", .method = "Roberts", .setting = std::to_string(k) + " turned boxes", .median_ms = ms,
                        .error = a.compared ? double(a.wrong) / double(a.compared) : 0,
                        .error_name = "share of sampled edge points whose visibility differs from rays in world space",
                        .wrong = a.wrong, .wrong_name = "edge points wrong", .wrong_must_be_zero = true, .extra = extra});
    }
    return rows;
}

// Its section of the report (analysis/measurement.h report_sections)
const ReportSection roberts_report{measure_roberts, {{"hidden lines", "Roberts' hidden lines: sampled edge points against rays in world space"}}};

}  // namespace hsr::analysis
