// SPDX-License-Identifier: MIT
// The cost of being a step-through machine, measured side by side in one run (figures, not tests):
//   build/tests/bench/hsr_bench --benchmark_filter=ClipCost --benchmark_counters_tabular=true
// For each clipper, the same random primitives go through (1) the straight-line formula written with no events
// (clipping/straight_clip.h, bit for bit the machine's answers), (2) the machine drained to its end (every event
// made and dropped), and (3) the machine recorded by the player as the window does (events stored, keyframes
// taken). Each is timed as the median of 5 runs; the counters give ns per primitive and per event and the ratios.
#include <algorithm>
#include <chrono>
#include <random>

#include <benchmark/benchmark.h>

#include "clipping/straight_clip.h"
#include "clipping/cohen_sutherland.h"
#include "clipping/liang_barsky.h"
#include "clipping/sutherland_hodgman.h"
#include "analysis/measurement.h"
#include "bench_points.h"
#include "state/clip_session.h"

using namespace hsr::algo;
using namespace hsr::viz;

namespace {

using hsr::bench::random_clip_point;

double median_ms(const std::function<void()>& f) { return hsr::analysis::median_ms(5, f); }

void BM_ClipCost(benchmark::State& state) {
    const auto algorithm = ClipAlgorithm(state.range(0));
    const bool polygons = algorithm == ClipAlgorithm::sutherland_hodgman;
    const int n = polygons ? 20'000 : 100'000;
    std::mt19937_64 rng(5);
    ClipJob job{.space = ClipSpace::homogeneous};
    for (int i = 0; i < n; ++i) {
        if (polygons) job.polygons.push_back({i + 1, {random_clip_point(rng), random_clip_point(rng), random_clip_point(rng), random_clip_point(rng)}});
        else job.segments.push_back({i + 1, random_clip_point(rng), random_clip_point(rng)});
    }
    for (auto _ : state) {
        std::size_t kept = 0, events = 0;
        const double straight = median_ms([&] {
            kept = 0;
            for (const auto& s : job.segments)
                kept += (algorithm == ClipAlgorithm::liang_barsky ? plain_liang_barsky(s.p1, s.p2)
                                                                  : plain_cohen_sutherland(s.p1, s.p2)).has_value();
            for (const auto& p : job.polygons) kept += !plain_sutherland_hodgman(p.vertices).empty();
        });
        benchmark::DoNotOptimize(kept);
        const double drained = median_ms([&] {
            events = 0;
            auto m = clip_scene(job, algorithm);
            for (const auto& e : m) events += 1 + 0 * e.index();
            benchmark::DoNotOptimize(&m.result());  // a pointer: Benchmark 1.8 deprecates const references
        });
        const double recorded = median_ms([&] {
            ClipPlayer player(clip_scene(job, algorithm), initial_view(job, algorithm));
            player.seek_end();
            benchmark::DoNotOptimize(player.known());
        });
        state.counters["primitives"] = n;
        state.counters["events_per_prim"] = double(events) / n;
        state.counters["straight_ns_per_prim"] = straight * 1e6 / n;
        state.counters["drained_ns_per_prim"] = drained * 1e6 / n;
        state.counters["recorded_ns_per_prim"] = recorded * 1e6 / n;
        state.counters["drained_over_straight"] = drained / straight;
        state.counters["recorded_over_drained"] = recorded / drained;
        state.counters["drained_ns_per_event"] = drained * 1e6 / double(events);
        state.counters["recording_ns_per_event"] = (recorded - drained) * 1e6 / double(events);
    }
}

}  // namespace

BENCHMARK(BM_ClipCost)->ArgName("algorithm")->Arg(0)->Arg(1)->Arg(2)->Iterations(1)->Unit(benchmark::kMillisecond);
