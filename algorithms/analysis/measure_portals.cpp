// SPDX-License-Identifier: MIT
// Cells and portals: the PVS's slack (pairs it holds that sampled rays never reach) and missed cells (must be 0),
// and portal_render with exact and with bounding-box frusta: polygons drawn, and polygons a ray cast sees that it
// did not draw (must be 0).
#include <algorithm>

#include "analysis/measurement.h"
#include "analysis/portal_coverage.h"
#include "portals/cell_bsp.h"
#include "scene/load_scene.h"
#include "scene/random_scene.h"

namespace hsr::analysis {

std::vector<Measurement> measure_portals(const ReportOptions& o) {
    std::vector<std::pair<std::string, algo::Scene>> scenes;
    for (const char* file : {"cells_lecture.toml", "cells_ring.toml", "cells_general.toml"})
        scenes.emplace_back(file, algo::load_scene(o.scenes_dir + "/" + file));
    const std::uint32_t side = o.quick ? 5 : 12;
    scenes.emplace_back("maze " + std::to_string(side) + "×" + std::to_string(side), algo::cell_maze({.rows = side, .cols = side}));

    std::vector<Measurement> rows;
    plan_runs(o, int(scenes.size()) * 3);  // the PVS, then portal_render with exact and with bounding-box frusta
    for (const auto& [name, scene] : scenes) {
        const algo::CellModel model = algo::cell_model(scene);
        const algo::CellBsp bsp = algo::build_cell_bsp(model);
        algo::Pvs pvs;
        const double pvs_ms = median_ms(o, [&] { pvs = algo::build_pvs(&model).run_to_end(); });
        const PvsSampling sampled = sample_pvs(model, pvs, o.quick ? 200 : 1000, 7);
        rows.push_back({.family = "portals", .method = "PVS (stab trees)", .setting = name, .median_ms = pvs_ms,
                        .error = sampled.pairs ? double(sampled.slack) / double(sampled.pairs) : 0,
                        .error_name = "PVS slack: share of pairs in the PVS no sampled ray reaches",
                        .wrong = sampled.missed, .wrong_name = "cells reached outside the PVS", .wrong_must_be_zero = true,
                        .extra = std::to_string(sampled.slack) + " of " + std::to_string(sampled.pairs) + " pairs never reached"});
        const algo::Viewport vp = o.quick ? algo::Viewport{48, 36} : algo::Viewport{128, 96};
        for (const bool box : {false, true}) {
            algo::PortalRenderResult r;
            const double ms = median_ms(o, [&] {
                r = algo::portal_render(&model, &bsp, &pvs, model.camera, {.bounding_box_frusta = box}).run_to_end();
            });
            const Coverage c = portal_coverage(model, r, vp);
            const auto drawn = std::count(r.drawn.begin(), r.drawn.end(), 1);
            rows.push_back({.family = "portals", .method = box ? "portal_render, bounding-box frusta" : "portal_render, exact frusta",
                            .setting = name, .median_ms = ms,
                            .error = drawn ? double(c.drawn_not_seen) / double(drawn) : 0,
                            .error_name = "slack: share of drawn polygons the ray cast does not see",
                            .wrong = std::uint64_t(c.missed), .wrong_name = "polygons seen but not drawn", .wrong_must_be_zero = true,
                            .extra = std::to_string(drawn) + " drawn, " + std::to_string(c.seen) + " seen"});
        }
    }
    return rows;
}

// Its section of the report (analysis/measurement.h report_sections)
const ReportSection portals_report{measure_portals, {{"portals", "Cells and portals: PVS and frustum slack, missed cells and polygons"}}};

}  // namespace hsr::analysis
