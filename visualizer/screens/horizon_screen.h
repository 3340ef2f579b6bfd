// SPDX-License-Identifier: MIT
// The floating horizon: a terrain's curves drawn nearest first on a screen of columns, with its two horizons.
#pragma once

#include "panels/horizon_panels.h"
#include "render/horizon_renderer.h"
#include "screens/screen.h"
#include "state/horizon_session.h"
#include "state/strings.h"

namespace hsr::viz {

template <>
class Screen<HorizonSession> : public ScreenDefaults {
public:
    void frame(const HorizonSession&, OrbitCamera&) const {}  // the terrain has a camera of its own (draw_scene)
    void draw_scene(const HorizonSession& s, SceneFrame& f) const {
        // The terrain on the right, in a camera of its own, or nothing where the canvas takes the whole view
        f.view_projection = horizon_terrain_camera(s.view(), f.view_w, f.view_h);
        if (f.view_projection)
            draw_horizon_terrain(s.view(), f.batches, f.labels, tr("horizon.nearest"),
                                 tr("horizon.farthest", {{"row", std::to_string(s.view().terrain->rows - 1)}}));
        else f.view_projection = glm::mat4(0);
        const algo::Terrain& t = *s.view().terrain;
        f.detail = tr("horizon.caption", {{"rows", std::to_string(t.rows)}, {"samples", std::to_string(t.columns)},
                                          {"columns", std::to_string(s.view().columns)}, {"elevation", algo::format_number(t.elevation)}});
    }
    void draw_panels(const HorizonSession& s, PanelFrame& f) const {
        const bool terrain_shown = horizon_terrain_camera(s.view(), f.view_w, f.view_h).has_value();
        horizon_canvas(s, 0, 0, terrain_shown ? horizon_canvas_share * f.view_w : f.view_w, f.view_h);
        horizon_state_panel(s, f.layout);
    }
};

}  // namespace hsr::viz
