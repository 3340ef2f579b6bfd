// SPDX-License-Identifier: MIT
// Clipping: each algorithm as the step-through machine (double) and as the straight-line formula in double and in
// float, on random segments and polygons of clip space, against the exact answer in GMP rationals.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/exact_clip.h"
#include "core/portable_random.h"
#include "analysis/measurement.h"
#include "clipping/straight_clip.h"
#include "clipping/cohen_sutherland.h"
#include "clipping/liang_barsky.h"
#include "clipping/sutherland_hodgman.h"

namespace hsr::analysis {
namespace {

using algo::PlainSegment;
using algo::Vec4;
using algo::Vec4Of;
using algo::plain_cohen_sutherland;
using algo::plain_liang_barsky;
using algo::plain_sutherland_hodgman;

// A point of clip space spread over the volume and well beyond it, a fifth of them behind the eye (w < 0), so
// that segments cross every plane and w = 0.
Vec4 random_clip_point(algo::PortableRandom& rng) {
    const double pw = rng.uniform(-1, 4);
    const double s = std::max(std::fabs(pw), 0.25);
    const auto u = [&] { return rng.uniform(-2.5, 2.5); };
    return {u() * s, u() * s, u() * s, pw};
}

template <class T>
Vec4Of<T> in_precision(const Vec4& v) { return Vec4Of<T>(v); }

struct ErrorTally {
    double max = 0, sum = 0;
    std::uint64_t points = 0, wrong = 0;
    void add(double e) { max = std::max(max, e), sum += e, ++points; }
    double mean() const { return points ? sum / double(points) : 0; }
};

double scale_of(const Vec4& a, const Vec4& b) {
    double s = 0;
    for (int i = 0; i < 4; ++i) s = std::max({s, std::fabs(a[i]), std::fabs(b[i])});
    return s;
}

// Segment answers as (visible, a, b) in double, whatever produced them.
struct SegmentAnswer {
    bool visible = false;
    Vec4 a{}, b{};
};

ErrorTally segment_errors(const std::vector<std::pair<Vec4, Vec4>>& in, const std::vector<ExactSegment>& exact,
                          const std::vector<SegmentAnswer>& got) {
    ErrorTally t;
    for (std::size_t k = 0; k < in.size(); ++k) {
        if (got[k].visible != exact[k].visible) {
            ++t.wrong;
            continue;
        }
        if (!got[k].visible) continue;
        const double scale = scale_of(in[k].first, in[k].second);
        t.add(relative_error(got[k].a, exact[k].a, scale));
        t.add(relative_error(got[k].b, exact[k].b, scale));
    }
    return t;
}

std::string mean_text(double mean) {
    char b[48];
    std::snprintf(b, sizeof b, "mean error %.3e", mean);
    return b;
}

Measurement row(std::string method, std::string setting, double ms, const ErrorTally& t, const char* wrong_name) {
    return {.family = "clipping", .method = std::move(method), .setting = std::move(setting), .median_ms = ms,
            .error = t.max, .error_name = "largest relative error of a clipped vertex", .wrong = t.wrong,
            .wrong_name = wrong_name, .wrong_must_be_zero = false,
            .extra = mean_text(t.mean())};
}

}  // namespace

std::vector<Measurement> measure_clipping(const ReportOptions& o) {
    plan_runs(o, 2 + 4 + 3);  // the segment machines, the segments' straight lines, Sutherland–Hodgman's three
    algo::PortableRandom rng(2026);
    const std::size_t segments = o.quick ? 2000 : 20000, polygons = o.quick ? 300 : 3000;
    std::vector<std::pair<Vec4, Vec4>> segs(segments);
    for (auto& s : segs) s = {random_clip_point(rng), random_clip_point(rng)};
    std::vector<std::vector<Vec4>> polys(polygons);
    for (auto& p : polys) {
        p.resize(std::size_t(rng.integer(3, 6)));
        for (Vec4& v : p) v = random_clip_point(rng);
    }
    std::vector<ExactSegment> exact;
    for (const auto& [a, b] : segs) exact.push_back(exact_clip_segment(a, b, algo::ClipSpace::homogeneous));

    const std::string seg_setting = std::to_string(segments) + " random segments, w in [-1, 4]";
    const std::string poly_setting = std::to_string(polygons) + " random polygons of 3 to 6 vertices";
    std::vector<Measurement> rows;
    std::vector<SegmentAnswer> got(segs.size());

    // The machines, drained to the end, one per segment.
    const auto run_machine = [&](auto machine) {
        for (std::size_t k = 0; k < segs.size(); ++k) {
            const algo::SegmentClip c = machine(algo::ClipSegment{algo::PrimitiveId(k), segs[k].first, segs[k].second}, algo::ClipOptions{}).run_to_end();
            got[k] = {c.outcome != algo::ClipOutcome::rejected, c.a, c.b};
        }
    };
    const auto machine_row = [&](const char* name, auto machine) {
        const double ms = median_ms(o, [&] { run_machine(machine); });
        rows.push_back(row(std::string(name) + " machine (double)", seg_setting, ms, segment_errors(segs, exact, got), "wrong accept/reject"));
    };
    machine_row("cohen_sutherland", [](auto s, auto op) { return algo::cohen_sutherland(s, op); });
    machine_row("liang_barsky", [](auto s, auto op) { return algo::liang_barsky(s, op); });

    // The straight-line formulas in double and in float (float input: what a float clipper is given).
    const auto plain_row = [&]<class T>(const char* name, auto clip, T) {
        const double ms = median_ms(o, [&] {
            for (std::size_t k = 0; k < segs.size(); ++k) {
                const PlainSegment<T> c = clip(in_precision<T>(segs[k].first), in_precision<T>(segs[k].second));
                got[k] = c ? SegmentAnswer{true, Vec4(c->first), Vec4(c->second)} : SegmentAnswer{};
            }
        });
        rows.push_back(row(std::string(name) + (sizeof(T) == 4 ? " straight-line (float)" : " straight-line (double)"), seg_setting, ms,
                           segment_errors(segs, exact, got), "wrong accept/reject"));
    };
    plain_row("cohen_sutherland", [](auto a, auto b) { return plain_cohen_sutherland(a, b); }, double{});
    plain_row("cohen_sutherland", [](auto a, auto b) { return plain_cohen_sutherland(a, b); }, float{});
    plain_row("liang_barsky", [](auto a, auto b) { return plain_liang_barsky(a, b); }, double{});
    plain_row("liang_barsky", [](auto a, auto b) { return plain_liang_barsky(a, b); }, float{});

    // Sutherland–Hodgman: the machine and the straight-line formula in double and float.
    std::vector<std::vector<ExactPoint>> exact_polys;
    for (const auto& p : polys) exact_polys.push_back(exact_clip_polygon(p, algo::ClipSpace::homogeneous));
    std::vector<std::vector<Vec4>> out(polys.size());
    const auto polygon_tally = [&] {
        ErrorTally t;
        for (std::size_t k = 0; k < polys.size(); ++k) {
            if (out[k].empty() != exact_polys[k].empty()) {
                ++t.wrong;
                continue;
            }
            if (out[k].empty()) continue;
            double scale = 0;
            for (const Vec4& v : polys[k]) scale = std::max(scale, scale_of(v, v));
            t.add(vertex_set_error(out[k], exact_polys[k], scale));
        }
        return t;
    };
    double ms = median_ms(o, [&] {
        for (std::size_t k = 0; k < polys.size(); ++k)
            out[k] = algo::sutherland_hodgman(algo::ClipPolygon{algo::PrimitiveId(k), polys[k]}).run_to_end().vertices;
    });
    rows.push_back(row("sutherland_hodgman machine (double)", poly_setting, ms, polygon_tally(), "wrong empty/non-empty"));
    const auto plain_polygons = [&]<class T>(T) {
        const double t = median_ms(o, [&] {
            for (std::size_t k = 0; k < polys.size(); ++k) {
                std::vector<Vec4Of<T>> p;
                for (const Vec4& v : polys[k]) p.push_back(in_precision<T>(v));
                out[k].clear();
                for (const auto& v : plain_sutherland_hodgman(std::move(p))) out[k].emplace_back(v);
            }
        });
        rows.push_back(row(sizeof(T) == 4 ? "sutherland_hodgman straight-line (float)" : "sutherland_hodgman straight-line (double)",
                           poly_setting, t, polygon_tally(), "wrong empty/non-empty"));
    };
    plain_polygons(double{});
    plain_polygons(float{});
    return rows;
}

// Its section of the report (analysis/measurement.h report_sections)
const ReportSection clipping_report{measure_clipping, {{"clipping", "Clipping: error against GMP rationals"}}};

}  // namespace hsr::analysis
