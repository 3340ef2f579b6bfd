// SPDX-License-Identifier: MIT
// Figures for the z-buffer, scan-line and ray cast issue: pixels and triangles per second of the fill at
// 1024×1024 for 10^3 to 10^5 random triangles, with polygon-detail events and with every event; the same scenes'
// ray cast; and bytes per recorded event.
//   build/tests/bench/hsr_bench --benchmark_filter='ZBuffer|ScanLine|RayCast|EventBytes' --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cmath>

#include "raycast/ray_cast.h"
#include "scene/random_scene.h"
#include "state/event_log.h"
#include "zbuffer/scanline.h"
#include "zbuffer/zbuffer_fill.h"

using namespace hsr::algo;

namespace {

// n triangles whose size shrinks as their number grows, so that the depth complexity stays about the same
Scene scene_of(std::size_t n) {
    return random_triangles({.count = n, .seed = 42, .size = 1.5 / std::sqrt(double(n) / 1000), .near = 1, .far = 30});
}

constexpr Viewport full{1024, 1024};

void BM_ZBufferFill(benchmark::State& state) {
    const Scene scene = scene_of(std::size_t(state.range(0)));
    const auto detail = EventDetail(state.range(1));
    std::uint64_t tested = 0, events = 0;
    for (auto _ : state) {
        auto fill = zbuffer_fill(project_polygons(scene, full), zbuffer_options(scene, full, DepthFormat::int24, detail));
        for (const auto& e : fill) benchmark::DoNotOptimize(&e), ++events;
        tested += std::move(fill).result().tested;
    }
    state.counters["pixels_per_s"] = benchmark::Counter(double(tested), benchmark::Counter::kIsRate);
    state.counters["triangles_per_s"] = benchmark::Counter(double(scene.polygons.size() * state.iterations()), benchmark::Counter::kIsRate);
    state.counters["events"] = double(events) / double(state.iterations());
    state.SetLabel(detail == EventDetail::pixel ? "every event" : "polygon events");
}
BENCHMARK(BM_ZBufferFill)
    ->ArgsProduct({{1000, 10000, 100000}, {int(EventDetail::polygon), int(EventDetail::pixel)}})
    ->Unit(benchmark::kMillisecond);

void BM_ScanLine(benchmark::State& state) {
    const Scene scene = scene_of(std::size_t(state.range(0)));
    ScanLineOptions o = scan_line_options(scene, full, DepthFormat::int24);
    o.tell_crossings = false;
    for (auto _ : state) benchmark::DoNotOptimize(scan_line(project_polygons(scene, full), o).run_to_end().image.ids.data());
    state.counters["triangles_per_s"] = benchmark::Counter(double(scene.polygons.size() * state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ScanLine)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_RayCast(benchmark::State& state) {
    const Scene scene = scene_of(std::size_t(state.range(0)));
    const auto accel = Acceleration(state.range(1));
    const Viewport vp = accel == Acceleration::none ? Viewport{256, 256} : full;  // brute force at 1024² takes minutes
    std::uint64_t tests = 0;
    for (auto _ : state) tests += ray_cast(scene, {.viewport = vp, .acceleration = accel, .detail = RayDetail::ray}).run_to_end().tests;
    state.counters["rays_per_s"] = benchmark::Counter(double(vp.width) * vp.height * double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["tests_per_ray"] = double(tests) / (double(vp.width) * vp.height * double(state.iterations()));
    state.SetLabel(std::string(to_string(accel)) + " at " + std::to_string(vp.width) + "²");
}
BENCHMARK(BM_RayCast)
    ->Args({1000, int(Acceleration::none)})
    ->ArgsProduct({{1000, 10000, 100000}, {int(Acceleration::grid), int(Acceleration::octree)}})
    ->Unit(benchmark::kMillisecond);

// What recording a pixel-detail fill costs in the player's event log
void BM_EventBytes(benchmark::State& state) {
    const Scene scene = scene_of(1000);
    const Viewport vp{256, 256};
    std::size_t bytes = 0, events = 0;
    for (auto _ : state) {
        hsr::viz::EventLog<ZBufferEvent> log;
        for (const auto& e : zbuffer_fill(project_polygons(scene, vp), zbuffer_options(scene, vp, DepthFormat::int24))) log.push(e);
        log.shrink_to_fit();
        bytes = log.bytes(), events = log.size();
    }
    state.counters["events"] = double(events);
    state.counters["bytes_per_event"] = double(bytes) / double(events);
    state.counters["variant_bytes"] = double(sizeof(ZBufferEvent));
}
BENCHMARK(BM_EventBytes)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
