// SPDX-License-Identifier: MIT
// Figures for the cells-and-portals issue: pre-processing time and PVS size for 10 to 10^4 cells (a maze of rooms
// with some extra doors), and the runtime traversal's time, cells visited and polygons drawn against all of them,
// for exact and bounding-box frusta; and the slack of the PVS against 2D ray walks.
//   build/tests/bench/hsr_bench --benchmark_filter=Portal --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include <random>

#include "portals/plan_ray.h"
#include "portals/portal_render.h"
#include "scene/random_scene.h"

using namespace hsr::algo;

namespace {

CellMaze maze(std::int64_t cells) {
    const auto side = std::uint32_t(std::lround(std::sqrt(double(cells))));
    return {.rows = side, .cols = std::max<std::uint32_t>(1, std::uint32_t(cells) / side), .seed = 5, .extra_doors = 0.1};
}

void BM_PortalPvs(benchmark::State& state) {
    const CellModel model = cell_model(cell_maze(maze(state.range(0))));
    Pvs pvs;
    for (auto _ : state) pvs = build_pvs(&model).run_to_end();
    std::uint64_t pairs = 0;
    for (std::uint8_t v : pvs.matrix) pairs += v;
    state.counters["cells"] = double(pvs.cells);
    state.counters["pvs_per_cell"] = double(pairs) / pvs.cells;
    state.counters["tests"] = double(pvs.sightline_tests);
    state.counters["bounded"] = pvs.bounded ? 1 : 0;
    // slack: PVS entries that 200 random plan rays from each cell never reach (conservative, but how loose?)
    std::vector<std::uint8_t> seen(pvs.matrix.size(), 0);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> unit(0, 1), angle(0, 2 * M_PI);
    for (std::uint32_t c = 0; c < pvs.cells && c < 1000; ++c)
        for (int k = 0; k < 200; ++k) {
            const auto& o = model.cells[c].outline;  // rooms are squares: o[0] and o[2] are opposite corners
            const double u = unit(rng), v = unit(rng), a = angle(rng);
            const Vec2 p = o[0] + (o[2] - o[0]) * Vec2(0.01 + 0.98 * u, 0.01 + 0.98 * v);
            for (std::uint32_t s : cells_along_ray(model, c, p, {std::cos(a), std::sin(a)})) seen[std::size_t(c) * pvs.cells + s] = 1;
        }
    std::uint64_t slack = 0, checked = 0;
    for (std::uint32_t c = 0; c < pvs.cells && c < 1000; ++c)
        for (std::uint32_t d = 0; d < pvs.cells; ++d) {
            const std::size_t k = std::size_t(c) * pvs.cells + d;
            checked += pvs.matrix[k], slack += pvs.matrix[k] && !seen[k];
        }
    state.counters["slack_pct"] = 100.0 * double(slack) / double(std::max<std::uint64_t>(checked, 1));
}
BENCHMARK(BM_PortalPvs)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_CellBsp(benchmark::State& state) {
    const CellModel model = cell_model(cell_maze(maze(state.range(0))));
    CellBsp bsp;
    for (auto _ : state) bsp = build_cell_bsp(model);
    state.counters["nodes"] = double(bsp.tree.nodes.size());
    state.counters["depth"] = double(bsp.tree.depth);
}
BENCHMARK(BM_CellBsp)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_PortalRender(benchmark::State& state) {
    const CellModel model = cell_model(cell_maze(maze(state.range(0))));
    const CellBsp bsp = build_cell_bsp(model);
    const Pvs pvs = build_pvs(&model).run_to_end();
    const bool bbox = state.range(1) != 0;
    PortalRenderResult r;
    for (auto _ : state) r = portal_render(&model, &bsp, &pvs, model.camera, {.bounding_box_frusta = bbox}).run_to_end();
    std::size_t in_pvs = 0;
    for (std::uint32_t c : pvs.row(std::uint32_t(r.eye_cell))) in_pvs += model.cells[c].polygons.size();
    state.counters["visits"] = r.visits;
    state.counters["drawn"] = double(std::count(r.drawn.begin(), r.drawn.end(), 1));
    state.counters["in_pvs"] = double(in_pvs);
    state.counters["all"] = double(model.polygons.size());
}
BENCHMARK(BM_PortalRender)->ArgsProduct({{10, 100, 1000, 10000}, {0, 1}})->Unit(benchmark::kMicrosecond);

}  // namespace
