// SPDX-License-Identifier: MIT
// The culling pipeline on generated scenes: what each stage leaves out, the frame time against rendering every
// primitive, and visibility violations (front-face pixels the culled frame lost; must be 0 for the conservative
// stages). Detail culling is not conservative by design: its lost pixels are its error, not a violation. The
// occluder rows compare the stage's shapes (planar, proxies, solids) with and without fusion after back-face and
// frustum culling: what each leaves out, and the front-face pixels lost (0 for all: fusion and solids stay
// conservative). The walk rows follow an eye through the city (the window's W): the scene prepared once, a frame
// per step from the new eye, the median frame time per set of stages, and front-face pixels lost over the walk.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>

#include <glm/geometric.hpp>

#include "analysis/lost_pixels.h"
#include "analysis/measurement.h"
#include "culling/pipeline.h"
#include "scene/generated_scenes.h"

namespace hsr::analysis {

std::vector<Measurement> measure_culling(const ReportOptions& o) {
    const std::size_t n = o.quick ? 2000 : 30000;
    const algo::Viewport vp = o.quick ? algo::Viewport{96, 72} : algo::Viewport{320, 240};
    using S = algo::Stage;
    std::vector<Measurement> rows;
    using K = algo::OccluderKind;
    struct OccluderSetting {
        const char* name;
        K kind;
        bool fusion;
    };
    const OccluderSetting occluder_settings[] = {{"occluders: planar", K::planar, false}, {"occluders: proxies", K::proxy, false},
                                                 {"occluders: solid and planar", K::solid, false}, {"occluders: planar, fused", K::planar, true},
                                                 {"occluders: solid and planar, fused", K::solid, true}};
    struct WalkSetting {
        const char* name;
        std::vector<S> stages;
        K occluders;
        bool coherent;
    };
    const WalkSetting walk_settings[] = {{"walk: no culling", {}, K::planar, false},
                                         {"walk: back-face, frustum, occluders", {S::back_face, S::frustum, S::occluders}, K::planar, false},
                                         {"walk: back-face, frustum, solid occluders, fused", {S::back_face, S::frustum, S::occluders}, K::solid, false},
                                         {"walk: back-face, frustum, Hi-Z", {S::back_face, S::frustum, S::hiz}, K::planar, false},
                                         {"walk: back-face, frustum, Hi-Z from the previous frame", {S::back_face, S::frustum, S::hiz}, K::planar, true}};
    // scenes × (no culling, conservative stages, with detail, occluders), and the walks
    plan_runs(o, 3 * (3 + int(std::size(occluder_settings))) + int(std::size(walk_settings)));
    for (const auto& kind_and_scene : {std::pair{"city", algo::city_scene({.triangles = n})},
                                       std::pair{"field", algo::field_scene({.triangles = n})},
                                       std::pair{"spheres", algo::spheres_scene({.triangles = n})}}) {
        const char* kind = kind_and_scene.first;  // (a lambda may not capture a structured binding in clang 14)
        const algo::Scene& scene = kind_and_scene.second;
        const std::string setting = std::string(kind) + ", " + std::to_string(scene.polygons.size()) + " triangles";
        algo::PipelineResult all;
        const double all_ms = median_ms(o, [&] { all = algo::run_pipeline(scene, {.stages = {}, .viewport = vp}); });
        rows.push_back({.family = "culling", .method = "no culling (the reference)", .setting = setting, .median_ms = all_ms,
                        .error = 0, .error_name = "share of pixels lost", .wrong_name = "front-face pixels lost"});
        const auto run = [&](const char* name, std::vector<S> stages, bool conservative) {
            algo::PipelineResult r;
            const double ms = median_ms(o, [&] { r = algo::run_pipeline(scene, {.stages = stages, .viewport = vp}); });
            const std::uint64_t lost = lost_front_pixels(scene, r.frame, all.frame);
            std::string extra = "left out:";
            for (const algo::StageReport& s : r.stages)
                if (s.ran && s.stage != S::hse) extra += " " + std::string(to_string(s.stage)) + " " + std::to_string(s.left_out);
            rows.push_back({.family = "culling", .method = name, .setting = setting, .median_ms = ms,
                            .error = double(lost) / double(all.frame.image.ids.size()), .error_name = "share of pixels lost",
                            .wrong = lost, .wrong_name = "front-face pixels lost", .wrong_must_be_zero = conservative,
                            .extra = extra});
        };
        run("back-face, frustum, occluders, hiz", {S::back_face, S::frustum, S::occluders, S::hiz}, true);
        run("back-face, frustum, detail (2 px), occluders, hiz", {S::back_face, S::frustum, S::detail, S::occluders, S::hiz}, false);
        for (const OccluderSetting& c : occluder_settings) {
            algo::PipelineResult r;
            const double ms = median_ms(o, [&] {
                r = algo::run_pipeline(scene, {.stages = {S::back_face, S::frustum, S::occluders}, .viewport = vp, .occluders = c.kind, .fusion = c.fusion});
            });
            const std::uint64_t lost = lost_front_pixels(scene, r.frame, all.frame);
            const algo::StageReport& stage = r.stages[3];  // back-face, frustum, detail, occluders
            char stage_ms[32];
            std::snprintf(stage_ms, sizeof stage_ms, "%.2f", stage.milliseconds);
            rows.push_back({.family = "culling", .method = c.name, .setting = setting, .median_ms = ms,
                            .error = double(lost) / double(all.frame.image.ids.size()), .error_name = "share of pixels lost",
                            .wrong = lost, .wrong_name = "front-face pixels lost", .wrong_must_be_zero = true,
                            .extra = "occluders left out " + std::to_string(stage.left_out) + " of " + std::to_string(stage.in) + " in " + stage_ms + " ms"});
        }
    }
    // Walking through the city: one eye moving down a street and turning now and then, a frame per step
    const algo::Scene city = algo::city_scene({.triangles = n});
    const int frames = o.quick ? 24 : 60;
    std::vector<algo::Camera> path;
    for (algo::Camera c = city.camera; int(path.size()) < frames;) {
        path.push_back(c);
        const algo::Vec3 d = glm::normalize(c.target - c.eye);
        const double turn = path.size() % 8 == 7 ? 0.15 : 0.0;  // radians, now and then
        const algo::Vec3 ahead{d.x * std::cos(turn) - d.z * std::sin(turn), d.y, d.x * std::sin(turn) + d.z * std::cos(turn)};
        c.eye += algo::Vec3(ahead.x, 0, ahead.z) * 2.0, c.target = c.eye + ahead;  // 2 m a step, on the level
    }
    std::vector<algo::FrameDepth> every(path.size(), algo::FrameDepth{algo::Image(0, 0), {}, {}});
    for (const WalkSetting& w : walk_settings) {
        const algo::PipelineOptions po{.stages = w.stages, .viewport = vp, .occluders = w.occluders, .fusion = w.occluders == K::solid};
        algo::PreparedScene prepared = algo::prepare_scene(city, [&] {
            algo::PipelineOptions all = po;
            all.stages.assign(std::begin(algo::all_stages), std::end(algo::all_stages));
            return all;
        }());
        std::vector<double> frame_ms;
        std::uint64_t lost = 0, drawn = 0;
        median_ms(o, [&] {
            frame_ms.clear(), lost = 0, drawn = 0;
            std::vector<std::uint8_t> seen;
            algo::Scene at = city;  // the reference's scene, its camera moved along the path
            for (std::size_t k = 0; k < path.size(); ++k) {
                const auto t = std::chrono::steady_clock::now();
                algo::PipelineResult r = algo::run_frame(prepared, path[k], po, w.coherent ? seen : std::vector<std::uint8_t>{});
                frame_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count());
                if (w.coherent) seen = algo::seen_in(r, prepared.scene.polygons.size());
                drawn += r.stages.back().in;
                if (w.stages.empty()) every[k] = std::move(r.frame);  // the reference: every primitive, from the same eye
                else {
                    at.camera = path[k];
                    lost += lost_front_pixels(at, r.frame, every[k]);
                }
            }
        });
        std::sort(frame_ms.begin(), frame_ms.end());
        char extra[160];
        std::snprintf(extra, sizeof extra, "%d frames: median %.2f ms, slowest %.2f ms; %.0f primitives drawn per frame; built once in %.1f ms", frames,
                      frame_ms[frame_ms.size() / 2], frame_ms.back(), double(drawn) / double(frames), prepared.milliseconds);
        rows.push_back({.family = "culling", .method = w.name, .setting = "city, " + std::to_string(city.polygons.size()) + " triangles",
                        .median_ms = frame_ms[frame_ms.size() / 2], .error = 0, .error_name = "share of pixels lost", .wrong = lost,
                        .wrong_name = "front-face pixels lost", .wrong_must_be_zero = true, .extra = extra});
    }
    return rows;
}

// Its section of the report (analysis/measurement.h report_sections)
const ReportSection culling_report{measure_culling, {{"culling", "Culling pipeline: pixels lost, per scene"}}};

}  // namespace hsr::analysis
