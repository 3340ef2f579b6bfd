// SPDX-License-Identifier: MIT
// The general forms: the floor plan with its projectors, and the two images the forms render.
#pragma once

#include "panels/forms_panels.h"
#include "screens/screen.h"
#include "state/forms_session.h"
#include "state/strings.h"

namespace hsr::viz {

template <>
class Screen<FormsSession> : public ScreenDefaults {
public:
    void frame(const FormsSession&, OrbitCamera&) {}  // no 3D view: the canvas covers it
    void draw_scene(const FormsSession& s, SceneFrame& f) const {
        f.detail = tr("forms.caption", {{"pixels", std::to_string(s.view().input->pixels)}});
    }
    void draw_panels(const FormsSession& s, PanelFrame& f) const {
        const bool table_in_view = side_box_fits(f.view_w, forms_table_share);
        forms_canvas(s, 0, 0, table_in_view ? f.view_w * (1 - forms_table_share) : f.view_w, f.view_h);
        if (table_in_view) forms_table_box(s, f.view_w, f.view_h);
        forms_state_panel(s, table_in_view, f.layout);
    }
    bool two_d(const FormsSession&) const { return true; }
};

}  // namespace hsr::viz
