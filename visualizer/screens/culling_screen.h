// SPDX-License-Identifier: MIT
// Culling: a god's-eye view of the camera's frustum and the hierarchy's boxes coloured by what happened to them,
// or the view from the scene's own camera (key V); the pipeline and the machine's panel beside it. One screen for
// the four culling machines. W walks through the scene: the arrows and the mouse move the eye, each stage can be
// switched, and the pipeline runs again from every new eye (state/walkthrough.h).
#pragma once


#include "panels/culling_panels.h"
#include "panels/state_legend.h"
#include "render/culling_renderer.h"
#include "render/palette.h"
#include "screens/screen.h"
#include "screens/walk_mode.h"
#include "state/culling_session.h"
#include "state/strings.h"

namespace hsr::viz {

template <class Event, class Result>
class Screen<CullingSession<Event, Result>> : public ScreenDefaults {
public:
    using S = CullingSession<Event, Result>;
    void frame(const S& s, OrbitCamera& camera) {
        depth_for_.reset();
        glm::vec3 centre(0);
        float radius = 1;
        culling_view_bounds(s.view(), centre, radius);
        camera.yaw = 0.6f, camera.pitch = 0.7f;  // from above and aside: the camera's frustum and what it leaves out
        frame_bounds(camera, centre, radius);
    }
    void draw_scene(const S& s, SceneFrame& f) const {
        const CullingWorld& w = *s.view().world;
        if (walk_.walking()) return walk_.draw_scene(f);  // the walker's eye, and what its frame drew
        draw_culling_view(s.view(), f.batches, f.labels);
        if (s.culling_machine() == algo::CullingMachine::bounds)  // the objects as the void table names them
            for (const SceneObject& o : w.objects) f.labels.push_back({o.centre, o.name, palette::parameter});
        f.detail = tr(f.second_view ? "culling.caption_camera" : "culling.caption_above",
                      {{"primitives", std::to_string(w.scene.polygons.size())},
                       {"hierarchy", w.hierarchy.kind == algo::HierarchyKind::bvh ? tr("culling.bvh") : tr("culling.octree")}});
        if (f.second_view) f.view_projection = whole_width(w.scene.camera, f.aspect());  // the view from the scene's own camera
        if (legend_in_view(s)) f.covered.push_back(view_legend_rect(f.view_w, f.view_h, culling_legend_entries(s.view())));
    }
    void draw_panels(const S& s, PanelFrame& f) {
        if (walk_.walking()) return walk_.draw_panels(f);
        if (s.culling_machine() == algo::CullingMachine::hiz) {  // the Z-pyramid, rebuilt when a primitive is rendered
            if (depth_for_ != s.view().rendered.size()) depth_ = rendered_depth(s.view()), depth_for_ = s.view().rendered.size();
            zpyramid_canvas(s.view(), depth_, 0, 0, f.view_w, f.view_h);
        }
        if (legend_in_view(s)) view_legend(f.view_w, f.view_h, culling_legend_entries(s.view()));  // the boxes' colours
        culling_state_panel(s, f.layout, legend_in_view(s));
    }

    // Walking (W): the lesson's stages on at the start, its occluder shapes, from the lesson's camera
    bool apply(S& s, const UiActions& a) {
        const CullingWorld& w = *s.view().world;
        const algo::OcclusionOptions occlusion = occlusion_options(s.lesson());
        walk_.apply(a, w.scene, algo::parse_stages(s.lesson().cull),
                    {.hierarchy = w.hierarchy.kind, .detail_pixels = w.detail_pixels, .occluders = occlusion.kind, .fusion = occlusion.fusion});
        return false;
    }
    bool pointer(const S&, const Pointer& p, const ViewGeometry&, UiActions&) { return walk_.pointer(p); }
    bool walking(const S&) const { return walk_.walking(); }

private:
    // the legend in the view's corner, leaving the column's room to the pipeline; Hi-Z's pyramid covers the view
    static bool legend_in_view(const S& s) { return s.culling_machine() != algo::CullingMachine::hiz; }
    WalkMode walk_;
    std::vector<std::uint32_t> depth_;     // the depth buffer of the primitives rendered so far (Hi-Z)
    std::optional<std::size_t> depth_for_;  // how many primitives depth_ holds
};

}  // namespace hsr::viz
