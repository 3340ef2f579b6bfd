// SPDX-License-Identifier: MIT
// BSP build and traversal at 10^3, 10^4 and 10^5 polygons, per splitter rule (figures, not tests):
//   build/tests/bench/hsr_bench --benchmark_filter=Bsp --benchmark_counters_tabular=true
// random: small triangles at random in a cube of side 100 (few of them cross a plane far away);
// structured: the walls of a grid of boxes (a city block plan: many coplanar and parallel polygons).
#include <chrono>
#include <cmath>
#include <map>
#include <string>
#include <random>

#include <benchmark/benchmark.h>

#include "bsp/bsp_tree.h"

using namespace hsr::algo;

namespace {

std::vector<BspInput> random_triangles(int n) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> at(0, 100), r(-1, 1);
    std::vector<BspInput> out;
    for (int i = 0; i < n; ++i) {
        const Vec3 c(at(rng), at(rng), at(rng));
        out.push_back({i + 1, {c + Vec3(r(rng), r(rng), r(rng)), c + Vec3(r(rng), r(rng), r(rng)),
                               c + Vec3(r(rng), r(rng), r(rng))}});
    }
    return out;
}

std::vector<BspInput> box_walls(int n) {  // n/4 boxes on a grid, four walls each
    std::vector<BspInput> out;
    const int side = int(std::ceil(std::sqrt(n / 4.0)));
    for (int i = 0; i < side && int(out.size()) < n; ++i)
        for (int j = 0; j < side && int(out.size()) < n; ++j) {
            const double x = 3.0 * i, z = 3.0 * j, h = 1 + (i * 7 + j * 3) % 5;
            const Vec3 a(x, 0, z), b(x + 2, 0, z), c(x + 2, 0, z + 2), d(x, 0, z + 2), up(0, h, 0);
            for (auto [p, q] : {std::pair{a, b}, {b, c}, {c, d}, {d, a}})
                out.push_back({int(out.size()) + 1, {p, q, q + up, p + up}});
        }
    return out;
}

void run(benchmark::State& state, const std::vector<BspInput>& scene, SplitterRule rule) {
    for (auto _ : state) {
        auto t0 = std::chrono::steady_clock::now();
        const BspTree tree = build_bsp(scene, {.splitter = rule}).run_to_end();
        const double build = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        t0 = std::chrono::steady_clock::now();
        const auto order = traverse_bsp(&tree, Vec3(50, 50, -30)).run_to_end();
        const double traverse = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        state.counters["build_ms"] = build;
        state.counters["traverse_ms"] = traverse;
        state.counters["splits"] = double(tree.splits);
        state.counters["polygons_after"] = double(tree.polygons.size());
        state.counters["depth"] = double(tree.depth);
        state.counters["bounded"] = tree.bounded ? 1 : 0;
        benchmark::DoNotOptimize(order.size());
    }
}

// Scenes are made once per size and kind, and shared by the four rules.
const std::vector<BspInput>& scene(const char* kind, int n) {
    static std::map<std::pair<std::string, int>, std::vector<BspInput>> scenes;
    auto& s = scenes[{kind, n}];
    if (s.empty()) s = std::string(kind) == "random" ? random_triangles(n) : box_walls(n);
    return s;
}
void BM_BspRandom(benchmark::State& state) {
    run(state, scene("random", int(state.range(0))), SplitterRule(state.range(1)));
}
void BM_BspStructured(benchmark::State& state) {
    run(state, scene("structured", int(state.range(0))), SplitterRule(state.range(1)));
}

void rules(benchmark::internal::Benchmark* b) {
    for (int n : {1000, 10000, 100000})
        for (int rule = 0; rule < 4; ++rule) b->Args({n, rule});
    b->ArgNames({"n", "rule"})->Iterations(1)->Unit(benchmark::kMillisecond);
}

}  // namespace

BENCHMARK(BM_BspRandom)->Apply(rules);
BENCHMARK(BM_BspStructured)->Apply(rules);
