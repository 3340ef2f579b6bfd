// SPDX-License-Identifier: MIT
// The A-buffer: fat pixels with their sub-samples and fragment lists; a click on a pixel opens its list.
#pragma once

#include <optional>
#include <utility>

#include "panels/abuffer_panels.h"
#include "screens/screen.h"
#include "state/abuffer_session.h"
#include "state/strings.h"

namespace hsr::viz {

template <>
class Screen<ABufferSession> : public ScreenDefaults {
public:
    void frame(const ABufferSession&, OrbitCamera&) { selected_.reset(); }  // no 3D view: the canvas covers it
    void draw_scene(const ABufferSession& s, SceneFrame& f) const {
        const algo::Viewport vp = s.view().input->viewport;
        f.detail = tr("abuffer.caption", {{"width", std::to_string(vp.width)}, {"height", std::to_string(vp.height)},
                                          {"m", std::to_string(s.view().input->mask_size)}});
    }
    void draw_panels(const ABufferSession& s, PanelFrame& f) const {
        const bool list_in_view = abuffer_canvas(s, selected_, 0, 0, f.view_w, f.view_h);
        abuffer_state_panel(s, selected_, list_in_view, f.layout);
    }
    // A click on a fat pixel opens its list in the state box; a click on it again (or off the grid) closes it.
    bool pointer(const ABufferSession& s, const Pointer& p, const ViewGeometry& g, UiActions&) {
        if (p.kind != Pointer::Kind::press || p.right || g.overlay_open) return false;
        const FatGrid grid = abuffer_grid(s, 0, 0, g.width, g.height);
        const algo::Viewport vp = s.view().input->viewport;
        const int px = int(std::floor((p.x - grid.x0) / grid.cell)), py = int(std::floor((p.y - grid.y0) / grid.cell));
        const bool on_grid = px >= 0 && py >= 0 && px < vp.width && py < vp.height;
        if (!on_grid || selected_ == std::pair{px, py}) selected_.reset();
        else selected_ = std::pair{px, py};
        return on_grid;
    }

private:
    std::optional<std::pair<int, int>> selected_;
};

}  // namespace hsr::viz
