// SPDX-License-Identifier: MIT
// The scan-line algorithm: the edge tables and the one-line z-buffer over the grid's rows.
#pragma once

#include "panels/scanline_panels.h"
#include "screens/screen.h"
#include "state/scanline_session.h"
#include "state/strings.h"

namespace hsr::viz {

template <>
class Screen<ScanLineSession> : public ScreenDefaults {
public:
    void frame(const ScanLineSession&, OrbitCamera&) const {}  // no 3D view: the canvas covers it
    void draw_scene(const ScanLineSession& s, SceneFrame& f) const {
        f.detail = tr(s.classic() ? "scanline.detail_classic" : "scanline.detail", {{"width", std::to_string(s.lesson().grid.width)},
                                          {"height", std::to_string(s.lesson().grid.height)},
                                          {"format", window_strings().name(algo::to_string(s.lesson().depth_format))}});
    }
    void draw_panels(const ScanLineSession& s, PanelFrame& f) const {
        if (const float share = scanline_foot_share(s, f.view_w, f.view_h); share > 0) {  // the table under the image
            scanline_canvas(s, 0, 0, f.view_w, f.view_h * (1 - share));
            scanline_tables_foot_box(s, f.view_w, f.view_h, share, f.actions);
        } else if (side_box_fits(f.view_w, scanline_tables_share)) {  // the tables beside the image, in the view
            scanline_canvas(s, 0, 0, f.view_w * (1 - scanline_tables_share), f.view_h);
            scanline_tables_box(s, f.view_w, f.view_h, f.actions);
        } else {
            scanline_canvas(s, 0, 0, f.view_w, f.view_h);
            scanline_state_panel(s, f.layout, f.actions);
        }
    }
    bool apply(ScanLineSession& s, const UiActions& a) {
        if (!a.find_piercings) return false;
        s.set_find_piercings(*a.find_piercings);
        return true;
    }
};

}  // namespace hsr::viz
