// SPDX-License-Identifier: MIT
// Cells and portals: the floor plan (the PVS being filled, or portal_render's frusta with a draggable eye), and for
// portal_render the 3D walk-through (key V).
#pragma once

#include "panels/portal_panels.h"
#include "render/portal_renderer.h"
#include "screens/screen.h"
#include "state/portal_session.h"
#include "state/strings.h"

namespace hsr::viz {

inline std::string portal_detail() { return tr("portals.caption"); }

template <>
class Screen<PvsSession> : public ScreenDefaults {
public:
    void frame(const PvsSession&, OrbitCamera&) const {}  // no 3D view: the plan covers it
    void draw_scene(const PvsSession&, SceneFrame& f) const { f.detail = portal_detail(); }
    void draw_panels(const PvsSession& s, PanelFrame& f) const {
        portal_plan_canvas(s, 0, 0, f.view_w, f.view_h);
        pvs_state_panel(s, f.layout);
    }
};

template <>
class Screen<PortalRenderSession> : public ScreenDefaults {
public:
    void frame(const PortalRenderSession& s, OrbitCamera& camera) const {
        glm::vec3 centre(0);
        float radius = 1;
        portal_view_bounds(s.view().world->model, centre, radius);
        camera.yaw = 0.3f, camera.pitch = 0.9f;  // from above, to look into the rooms (they have no ceilings)
        frame_bounds(camera, centre, radius);
    }
    void draw_scene(const PortalRenderSession& s, SceneFrame& f) const {
        if (f.second_view) draw_portal_view(s.view(), f.batches, f.labels);
        f.detail = portal_detail();
    }
    void draw_panels(const PortalRenderSession& s, PanelFrame& f) const {
        if (!f.second_view) portal_plan_canvas(s, 0, 0, f.view_w, f.view_h, f.actions);
        portal_state_panel(s, f.second_view, f.layout, f.actions);
    }
    bool apply(PortalRenderSession& s, const UiActions& a) const {
        if (!a.move_eye) return false;
        s.move_eye(algo::plan_point(*a.move_eye));
        return true;
    }
};

}  // namespace hsr::viz
