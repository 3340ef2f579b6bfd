// SPDX-License-Identifier: MIT
// Culling: a god's-eye view of the camera's frustum and the hierarchy's boxes coloured by what happened to them,
// or the view from the scene's own camera (key V); the pipeline and the machine's panel beside it. One screen for
// the four culling machines.
#pragma once

#include <cmath>

#include <glm/trigonometric.hpp>

#include "panels/culling_panels.h"
#include "render/culling_renderer.h"
#include "screens/screen.h"
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
        draw_culling_view(s.view(), f.batches, f.labels);
        f.detail = tr(f.second_view ? "culling.caption_camera" : "culling.caption_above",
                      {{"primitives", std::to_string(w.scene.polygons.size())},
                       {"hierarchy", w.hierarchy.kind == algo::HierarchyKind::bvh ? tr("culling.bvh") : tr("culling.octree")}});
        if (f.second_view) {  // the view from the scene's own camera
            algo::Camera eye = w.scene.camera;
            eye.aspect = f.aspect();
            // a canvas narrower than the lesson's image shows all of its width (and more above and below): what the
            // pipeline renders at the sides stays in the picture
            if (const double wide = w.scene.camera.aspect / eye.aspect; wide > 1) {
                if (eye.projection == algo::Projection::perspective)
                    eye.fov_y = 2 * glm::degrees(std::atan(std::tan(glm::radians(eye.fov_y) / 2) * wide));
                else
                    eye.box[2] *= wide, eye.box[3] *= wide;
            }
            f.view_projection = glm::mat4(algo::view_projection(eye));
        }
    }
    void draw_panels(const S& s, PanelFrame& f) {
        if (s.culling_machine() == algo::CullingMachine::hiz) {  // the Z-pyramid, rebuilt when a primitive is rendered
            if (depth_for_ != s.view().rendered.size()) depth_ = rendered_depth(s.view()), depth_for_ = s.view().rendered.size();
            zpyramid_canvas(s.view(), depth_, 0, 0, f.view_w, f.view_h);
        }
        culling_state_panel(s, f.layout);
    }

private:
    std::vector<std::uint32_t> depth_;     // the depth buffer of the primitives rendered so far (Hi-Z)
    std::optional<std::size_t> depth_for_;  // how many primitives depth_ holds
};

}  // namespace hsr::viz
