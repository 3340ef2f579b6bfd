// Figures for the depth-sort issue: sort-and-resolve time, pairs examined, which test settled them, moves and
// splits, for 10^2 to 10^4 random triangles (the O(P log P) sort and the O(P^2) pair scan in our own numbers).
//   build/tests/bench/hsr_bench --benchmark_filter=DepthSort --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cmath>

#include "depth_sort/depth_sort.h"
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

}  // namespace
