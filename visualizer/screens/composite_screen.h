// SPDX-License-Identifier: MIT
// Alpha compositing: one pixel's layers, composited step by step; the canvas covers the view.
#pragma once

#include "panels/composite_panels.h"
#include "screens/screen.h"
#include "state/composite_session.h"
#include "state/strings.h"

namespace hsr::viz {

template <>
class Screen<CompositeSession> : public ScreenDefaults {
public:
    void frame(const CompositeSession&, OrbitCamera&) const {}  // no 3D view: the canvas covers it
    void draw_scene(const CompositeSession& s, SceneFrame& f) const {
        f.detail = tr("composite.detail", {{"layers", std::to_string(s.view().layers->size())}});
    }
    void draw_panels(const CompositeSession& s, PanelFrame& f) const {
        composite_canvas(s, 0, 0, f.view_w, f.view_h);
        composite_state_panel(s, f.layout);
    }
};

}  // namespace hsr::viz
