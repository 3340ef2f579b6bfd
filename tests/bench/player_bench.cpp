// SPDX-License-Identifier: MIT
// Seek latency and bytes per stored event of the player on traces of at least 10^6 events (figures, not tests).
//   build/tests/bench/hsr_bench --benchmark_counters_tabular=true
// Each benchmark builds one trace, pulls it whole (as the window's End key does), then times 2000 seeks to random
// steps and 2000 single steps back, and reports the median and the largest of each, in milliseconds.
#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

#include <benchmark/benchmark.h>

#include "clipping/cohen_sutherland.h"
#include "bench_points.h"
#include "state/clip_session.h"

using namespace hsr::algo;
using namespace hsr::viz;

namespace {

using hsr::bench::random_clip_point;

// Many segments, clipped one after another by Cohen–Sutherland: a large view (every primitive) and small events.
ClipJob many_segments(int n) {
    std::mt19937_64 rng(1);
    ClipJob job{.space = ClipSpace::homogeneous};
    for (int i = 0; i < n; ++i) job.segments.push_back({i + 1, random_clip_point(rng), random_clip_point(rng)});
    return job;
}

// One polygon of n vertices through the Sutherland–Hodgman pipeline: a large working state (the stage lists).
ClipJob one_big_polygon(int n) {
    ClipJob job{.space = ClipSpace::cube};
    ClipPolygon p{1, {}};
    for (int i = 0; i < n; ++i) {
        const double a = 2 * 3.141592653589793 * i / n, r = 1.3 + 0.2 * std::sin(40 * a);  // crosses x and y planes
        p.vertices.push_back({r * std::cos(a), r * std::sin(a), 0.3 * std::sin(7 * a), 1});
    }
    job.polygons.push_back(std::move(p));
    return job;
}

// Bytes in use on the heap, large (mmapped) blocks included: uordblks alone leaves those out.
std::size_t heap_in_use() {
    const struct mallinfo2 m = mallinfo2();
    return m.uordblks + m.hblkhd;
}

double ms_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

void report(benchmark::State& state, std::vector<double>& ms, const char* name) {
    std::sort(ms.begin(), ms.end());
    state.counters[std::string(name) + "_median_ms"] = ms[ms.size() / 2];
    state.counters[std::string(name) + "_max_ms"] = ms.back();
}

void seek_benchmark(benchmark::State& state, const ClipJob& job, ClipAlgorithm algorithm) {
    for (auto _ : state) {
        const std::size_t heap_before = heap_in_use();
        ClipPlayer player(clip_scene(job, algorithm), initial_view(job, algorithm));
        player.seek_end();  // pulls every event and takes every keyframe
        const std::size_t n = player.known();
        const std::size_t heap = heap_in_use() - heap_before;

        std::mt19937_64 rng(7);
        std::uniform_int_distribution<std::size_t> any(0, n);
        std::vector<double> seek_ms, back_ms;
        for (int i = 0; i < 2000; ++i) {
            const std::size_t k = any(rng);
            auto t = std::chrono::steady_clock::now();
            player.seek(k);
            seek_ms.push_back(ms_since(t));
            t = std::chrono::steady_clock::now();
            player.step_back();
            back_ms.push_back(ms_since(t));
            benchmark::DoNotOptimize(&player.view().active);
        }
        state.counters["events"] = double(n);
        state.counters["log_bytes_per_event"] = double(player.log().bytes()) / double(n);
        state.counters["keyframes"] = double(player.keyframe_count());
        // log + keyframes + view + the machine's own state, as malloc counts it
        state.counters["all_bytes_per_event"] = double(heap) / double(n);
        report(state, seek_ms, "seek");
        report(state, back_ms, "back");
    }
}

void BM_SeekManySegments(benchmark::State& state) {
    static const ClipJob job = many_segments(110'000);
    seek_benchmark(state, job, ClipAlgorithm::cohen_sutherland);
}
void BM_SeekOneBigPolygon(benchmark::State& state) {
    static const ClipJob job = one_big_polygon(220'000);
    seek_benchmark(state, job, ClipAlgorithm::sutherland_hodgman);
}

// The cost of being a step-through machine: draining the events of one segment.
void BM_DrainCohenSutherland(benchmark::State& state) {
    std::mt19937_64 rng(3);
    std::vector<ClipSegment> segments;
    for (int i = 0; i < 1024; ++i) segments.push_back({i, random_clip_point(rng), random_clip_point(rng)});
    std::size_t i = 0;
    for (auto _ : state) {
        auto m = cohen_sutherland(segments[i++ % segments.size()]);
        benchmark::DoNotOptimize(&m.run_to_end());
    }
}

}  // namespace

BENCHMARK(BM_SeekManySegments)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SeekOneBigPolygon)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DrainCohenSutherland);
BENCHMARK_MAIN();
