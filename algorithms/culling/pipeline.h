// SPDX-License-Identifier: MIT
// The culling pipeline of the lectures: cheap tests leave out what cannot be seen before the expensive
// hidden-surface algorithm runs. Stages, in order (a scene or lesson names those it needs; the others are shown as
// left out of the pipeline):
//   back-face → frustum (hierarchical) → detail → occluders → portals → hierarchical z-buffer → HSE
// A floor-plan scene plays as its rooms' polygons (cell_model), and its portals stage keeps what portal_render draws
// from the camera; other scenes have no portals stage to run. Each stage reports the primitives it got, left out and
// passed on, and its time; the hidden-surface stage is the z-buffer, and the hierarchical z-buffer renders as it
// culls.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "culling/hierarchy.h"
#include "culling/occluders.h"
#include "portals/cell_bsp.h"
#include "portals/pvs.h"
#include "zbuffer/zbuffer_fill.h"

namespace hsr::algo {

enum class Stage : std::uint8_t { back_face, frustum, detail, occluders, portals, hiz, hse };
inline constexpr Stage all_stages[] = {Stage::back_face, Stage::frustum, Stage::detail, Stage::occluders, Stage::portals, Stage::hiz, Stage::hse};
std::string_view to_string(Stage s);
// "back-face,frustum,detail,occluders" → stages; InvalidInput naming an unknown one.
std::vector<Stage> parse_stages(std::string_view list);

struct PipelineOptions {
    std::vector<Stage> stages;       // which to run (hse always runs, last)
    Viewport viewport{640, 480};
    DepthFormat format = DepthFormat::int24;
    HierarchyKind hierarchy = HierarchyKind::octree;
    double detail_pixels = 2;        // the detail stage's threshold
    std::uint32_t max_occluders = 8;
    OccluderKind occluders = OccluderKind::planar;  // the occluders stage's: polygons, their proxies, or solids too
    bool fusion = false;                            // … and whether it fuses them
};

struct StageReport {
    Stage stage;
    bool ran = false;
    std::uint32_t in = 0, left_out = 0, passed = 0;
    double milliseconds = 0;
    // per polygon: reached this stage (kept by every stage before it). A stage counts what it leaves out among
    // these only, so that a lesson's machine run on them says the number the pipeline says.
    std::vector<std::uint8_t> candidates;
};

struct PipelineResult {
    std::vector<StageReport> stages;  // one per stage in pipeline order, those not run marked so
    std::vector<std::uint8_t> kept;   // per polygon (of the scene, or of a floor plan's rooms): reached the last stage
    FrameDepth frame{Image(0, 0), {}, {}};
    double hierarchy_milliseconds = 0;  // pre-processing (prepare_scene): the hierarchy, the solids, a plan's PVS
};

PipelineResult run_pipeline(const Scene& scene, const PipelineOptions& options);

// What stays the same from frame to frame when only the eye moves, made once: the polygons (a floor plan's rooms),
// the hierarchy, the solid occluders, and a floor plan's cell BSP and PVS. Walking through the scene runs frames
// on it (run_frame); run_pipeline is one frame on a scene prepared for it.
struct PreparedScene {
    std::optional<CellModel> model;  // a floor-plan scene's
    Scene scene;                     // the polygons the stages work on; its camera is the frame's
    Hierarchy hierarchy;
    std::vector<std::vector<std::uint32_t>> solids;  // when the occluders stage uses solid occluders
    std::optional<CellBsp> cell_bsp;
    std::optional<Pvs> pvs;
    double milliseconds = 0;  // the time it took
};
PreparedScene prepare_scene(const Scene& scene, const PipelineOptions& options);
// One frame from `camera` (the prepared scene's camera becomes it). `seen_before` (per polygon; empty: none): what
// the previous frame saw, which the Hi-Z stage draws first (frame-to-frame coherence).
PipelineResult run_frame(PreparedScene& prepared, const Camera& camera, const PipelineOptions& options,
                         const std::vector<std::uint8_t>& seen_before = {});
// What a frame saw: per polygon, whether some pixel shows it.
std::vector<std::uint8_t> seen_in(const PipelineResult& frame, std::size_t polygons);

}  // namespace hsr::algo
