// SPDX-License-Identifier: MIT
// Cells and portals: the floor plan (the PVS being filled, or portal_render's frusta with a draggable eye), and for
// portal_render the 3D walk-through (key V). W walks through the rooms with the culling pipeline's portals stage
// (screens/walk_mode.h).
#pragma once

#include "panels/portal_panels.h"
#include "render/portal_renderer.h"
#include "screens/screen.h"
#include "screens/walk_mode.h"
#include "state/portal_session.h"
#include "state/strings.h"

namespace hsr::viz {

inline std::string portal_detail() { return tr("portals.caption"); }

// A walk through the rooms starts with back-face and frustum culling and the portals stage on.
inline void walk_the_rooms(WalkMode& walk, const UiActions& a, const algo::Scene& plan) {
    walk.apply(a, plan, {algo::Stage::back_face, algo::Stage::frustum, algo::Stage::portals}, {});
}

template <>
class Screen<PvsSession> : public ScreenDefaults {
public:
    void frame(const PvsSession&, OrbitCamera&) const {}  // no 3D view: the plan covers it (but for a walk)
    void draw_scene(const PvsSession&, SceneFrame& f) const {
        if (walk_.walking()) return walk_.draw_scene(f);
        f.detail = portal_detail();
    }
    void draw_panels(const PvsSession& s, PanelFrame& f) const {
        if (walk_.walking()) return walk_.draw_panels(f);
        portal_plan_canvas(s, 0, 0, f.view_w, f.view_h);
        pvs_state_panel(s, f.layout);
    }
    bool apply(PvsSession& s, const UiActions& a) {
        walk_the_rooms(walk_, a, s.lesson().scene);
        return false;
    }
    bool pointer(const PvsSession&, const Pointer& p, const ViewGeometry&, UiActions&) { return walk_.pointer(p); }
    bool walking(const PvsSession&) const { return walk_.walking(); }

private:
    WalkMode walk_;
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
        if (walk_.walking()) return walk_.draw_scene(f);
        if (f.second_view) draw_portal_view(s.view(), f.batches, f.labels);
        f.detail = portal_detail();
    }
    void draw_panels(const PortalRenderSession& s, PanelFrame& f) const {
        if (walk_.walking()) return walk_.draw_panels(f);
        if (!f.second_view) portal_plan_canvas(s, 0, 0, f.view_w, f.view_h, f.actions);
        portal_state_panel(s, f.second_view, f.layout, f.actions);
    }
    bool apply(PortalRenderSession& s, const UiActions& a) {
        walk_the_rooms(walk_, a, s.lesson().scene);
        if (!a.move_eye || walk_.walking()) return false;
        s.move_eye(algo::plan_point(*a.move_eye));
        return true;
    }
    bool pointer(const PortalRenderSession&, const Pointer& p, const ViewGeometry&, UiActions&) { return walk_.pointer(p); }
    bool walking(const PortalRenderSession&) const { return walk_.walking(); }

private:
    WalkMode walk_;
};

}  // namespace hsr::viz
