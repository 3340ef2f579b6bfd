// SPDX-License-Identifier: MIT
// Figures for the depth-sort issue: sort-and-resolve time, pairs examined, which test settled them, moves and
// splits, for 10^2 to 10^4 random triangles (the O(P log P) sort and the O(P^2) pair scan in our own numbers).
//   build/tests/bench/hsr_bench --benchmark_filter=DepthSort --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cmath>

#include "depth_sort/depth_sort.h"
#include "scene/generated_scenes.h"
#include "scene/random_scene.h"

using namespace hsr::algo;

namespace {

void BM_DepthSort(benchmark::State& state) {
    const auto n = std::size_t(state.range(0));
    const std::vector<SortPolygon> input =
        sort_polygons(random_triangles({.count = n, .seed = 7, .size = 1.5 / std::sqrt(double(n) / 100), .near = 1, .far = 30}));
    DepthSortResult r;
    for (auto _ : state) r = depth_sort(input, {.max_splits = 1u << 20}).run_to_end();
    state.counters["pairs"] = double(r.pairs);
    state.counters["splits"] = double(r.splits);
    state.counters["moves"] = double(r.moves);
    const char* names[7] = {"by_x", "by_y", "by_3", "by_4", "by_5", "by_3s", "by_4s"};
    for (int t = 0; t < 7; ++t) state.counters[names[t]] = double(r.decided_by[t]);
    state.counters["bounded"] = r.bounded ? 1 : 0;
}
BENCHMARK(BM_DepthSort)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

// A generated field of 10^4 to 10^6 triangles: few z overlaps per polygon, so the time is the sort and the scan that
// finds them. Linear growth here means the scan stops at the first wholly nearer polygon (it once walked the whole
// list for every polygon drawn: 19 s at 10^6).
void BM_DepthSortField(benchmark::State& state) {
    const std::vector<SortPolygon> input = sort_polygons(field_scene({.triangles = std::size_t(state.range(0))}));
    DepthSortResult r;
    for (auto _ : state) r = depth_sort(input).run_to_end();
    state.counters["polygons"] = double(input.size());
    state.counters["pairs"] = double(r.pairs);
    state.counters["bounded"] = r.bounded ? 1 : 0;
}
BENCHMARK(BM_DepthSortField)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

}  // namespace
