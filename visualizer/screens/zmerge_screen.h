// SPDX-License-Identifier: MIT
// Z-merge: two frame and depth buffer pairs merged pixel by pixel.
#pragma once

#include "panels/zmerge_panels.h"
#include "screens/screen.h"
#include "state/zmerge_session.h"
#include "state/strings.h"

namespace hsr::viz {

template <>
class Screen<ZMergeSession> : public ScreenDefaults {
public:
    void frame(const ZMergeSession&, OrbitCamera&) const {}  // no 3D view: the canvas covers it
    void draw_scene(const ZMergeSession& s, SceneFrame& f) const {
        f.detail = tr("zmerge.caption", {{"width", std::to_string(s.lesson().grid.width)}, {"height", std::to_string(s.lesson().grid.height)},
                                         {"format", window_strings().name(algo::to_string(s.lesson().depth_format))}});
    }
    void draw_panels(const ZMergeSession& s, PanelFrame& f) const {
        zmerge_canvas(s, 0, 0, f.view_w, f.view_h);
        zmerge_state_panel(s, f.layout);
    }
};

}  // namespace hsr::viz
