// SPDX-License-Identifier: MIT
// The floating horizon: a terrain's curves drawn nearest first on a screen of columns, with its two horizons.
#pragma once

#include "panels/horizon_panels.h"
#include "screens/screen.h"
#include "state/horizon_session.h"
#include "state/strings.h"

namespace hsr::viz {

template <>
class Screen<HorizonSession> : public ScreenDefaults {
public:
    void frame(const HorizonSession&, OrbitCamera&) const {}  // no 3D view: the canvas covers it
    void draw_scene(const HorizonSession& s, SceneFrame& f) const {
        const algo::Terrain& t = *s.view().terrain;
        f.detail = tr("horizon.caption", {{"rows", std::to_string(t.rows)}, {"samples", std::to_string(t.columns)},
                                          {"columns", std::to_string(s.view().columns)}, {"elevation", algo::format_number(t.elevation)}});
    }
    void draw_panels(const HorizonSession& s, PanelFrame& f) const {
        horizon_canvas(s, 0, 0, f.view_w, f.view_h);
        horizon_state_panel(s, f.layout);
    }
};

}  // namespace hsr::viz
