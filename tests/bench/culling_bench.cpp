// SPDX-License-Identifier: MIT
// Figures for the culling issue: for each generated scene and size (10^3 to 10^6 triangles), the primitives each
// stage leaves out and its time, and the frame time with the whole pipeline against the z-buffer alone.
//   build/tests/bench/hsr_bench --benchmark_filter=Culling --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <algorithm>

#include "culling/pipeline.h"
#include "state/walkthrough.h"
#include "scene/generated_scenes.h"

using namespace hsr::algo;

namespace {

Scene scene_for(int kind, std::int64_t triangles) {
    const GeneratedScene g{.triangles = std::size_t(triangles), .seed = 3};
    return kind == 0 ? city_scene(g) : kind == 1 ? field_scene(g) : spheres_scene(g);
}

void BM_CullingPipeline(benchmark::State& state) {
    const Scene scene = scene_for(int(state.range(0)), state.range(1));
    const PipelineOptions o{.stages = {Stage::back_face, Stage::frustum, Stage::detail, Stage::occluders, Stage::hiz}, .viewport = {640, 480}};
    PipelineResult r;
    for (auto _ : state) r = run_pipeline(scene, o);
    state.SetLabel(scene.name);
    state.counters["polygons"] = double(scene.polygons.size());
    state.counters["tree_ms"] = r.hierarchy_milliseconds;
    const char* short_names[] = {"bf", "fr", "dt", "oc", "pt", "hz", "hse"};
    for (const StageReport& s : r.stages) {
        if (!s.ran) continue;
        state.counters[std::string(short_names[int(s.stage)]) + "_out"] = s.left_out;
        state.counters[std::string(short_names[int(s.stage)]) + "_ms"] = s.milliseconds;
    }
    state.counters["drawn"] = double(r.stages.back().in);
}
void BM_CullingNone(benchmark::State& state) {
    const Scene scene = scene_for(int(state.range(0)), state.range(1));
    PipelineResult r;
    for (auto _ : state) r = run_pipeline(scene, {.stages = {}, .viewport = {640, 480}});
    state.SetLabel(scene.name + ", z-buffer alone");
    state.counters["polygons"] = double(scene.polygons.size());
}
void sizes(benchmark::internal::Benchmark* b) {
    for (int kind = 0; kind < 3; ++kind)
        for (std::int64_t n : {1000, 10000, 100000, 1000000}) b->Args({kind, n});
    b->Unit(benchmark::kMillisecond)->Iterations(1);
}
BENCHMARK(BM_CullingPipeline)->Apply(sizes);
BENCHMARK(BM_CullingNone)->Apply(sizes);

// Walking through the city (state/walkthrough.h, key W in the window): 60 frames along one path at 320 × 240, the
// median and the slowest frame time per set of stages, and what the last stage drew on average.
//   build/tests/bench/hsr_bench --benchmark_filter=Walk --benchmark_counters_tabular=true
void BM_Walk(benchmark::State& state) {
    const Scene scene = city_scene({.triangles = std::size_t(state.range(1)), .seed = 3});
    using S = Stage;
    struct Setting {
        const char* name;
        std::vector<Stage> stages;
        PipelineOptions options;
        bool coherent;
    };
    const Setting settings[] = {
        {"no culling", {}, {}, false},
        {"back-face, frustum", {S::back_face, S::frustum}, {}, false},
        {"+ occluders", {S::back_face, S::frustum, S::occluders}, {}, false},
        {"+ solid occluders, fused", {S::back_face, S::frustum, S::occluders}, {.occluders = OccluderKind::solid, .fusion = true}, false},
        {"+ Hi-Z", {S::back_face, S::frustum, S::hiz}, {}, false},
        {"+ Hi-Z from the previous frame", {S::back_face, S::frustum, S::hiz}, {}, true},
    };
    const Setting& setting = settings[state.range(0)];
    std::vector<double> ms;
    double drawn = 0;
    for (auto _ : state) {
        hsr::viz::Walkthrough walk(scene, setting.stages, {320, 240}, setting.options);
        walk.set_coherent(setting.coherent);
        for (int k = 0; k < 60; ++k) {
            const PipelineResult& r = walk.frame();
            ms.push_back(walk.frame_ms());
            drawn += double(r.stages.back().in);
            if (k % 10 == 9) walk.walk(0, 1);  // a turn now and then, else straight on
            else walk.walk(1, 0);
        }
    }
    std::sort(ms.begin(), ms.end());
    state.SetLabel(std::string(setting.name) + ", " + std::to_string(scene.polygons.size()) + " polygons");
    state.counters["median_ms"] = ms[ms.size() / 2];
    state.counters["slowest_ms"] = ms.back();
    state.counters["drawn"] = drawn / double(ms.size());
}
BENCHMARK(BM_Walk)->ArgsProduct({{0, 1, 2, 3, 4, 5}, {3000, 30000}})->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
