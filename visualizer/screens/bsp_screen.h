// SPDX-License-Identifier: MIT
// BSP trees: the tree's splitting lines (2D) or planes (3D) over the scene; in a 2D lesson the eye, the segments'
// ends and the ground take gestures (drag the eye or an end, Shift+drag a new segment, right-click one away).
#pragma once

#include <cstdint>

#include "panels/bsp_panels.h"
#include "screens/screen.h"
#include "state/bsp_session.h"

namespace hsr::viz {

template <>
class Screen<BspSession> : public ScreenDefaults {
public:
    void frame(const BspSession& s, OrbitCamera& camera);
    void draw_scene(const BspSession& s, SceneFrame& f) const;
    void draw_panels(const BspSession& s, PanelFrame& f) const {
        bsp_painted_canvas(s, f.view_w, f.view_h, drives(s, f.second_view));
        const bool tree_in_view = side_box_fits(f.view_w);
        if (tree_in_view) bsp_tree_canvas(s, f.view_w, f.view_h);
        bsp_state_panel(s, tree_in_view, f.layout, f.actions);
    }
    // V in a 2D plan: drive mode, the arrows walk and turn the eye
    bool drives(const BspSession& s, bool second_view) const { return second_view && s.view().two_d; }
    bool pointer(const BspSession& s, const Pointer& p, const ViewGeometry& g, UiActions& out);
    bool apply(BspSession& s, const UiActions& a);
    std::optional<algo::Scene> edited_scene(const BspSession& s) const { return s.edited_scene(); }
    bool two_d(const BspSession& s) const { return s.view().two_d; }

private:
    bool dragging_eye_ = false;
    std::int64_t dragging_input_ = -1;       // the input whose vertex is dragged (−1: none) …
    std::size_t dragging_corner_ = 0;        // … and which of its vertices
    std::optional<glm::dvec3> drawing_from_;  // Shift+drag: where the new segment starts
    std::uint64_t shuffles_ = 0;              // each Shuffle another order, the same ones in every run
};

}  // namespace hsr::viz
