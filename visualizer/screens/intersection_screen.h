// SPDX-License-Identifier: MIT
// The intersection test: the scene, the rays and the volumes of the hierarchy they reach, in 3D.
#pragma once

#include "panels/intersection_panels.h"
#include "panels/state_legend.h"
#include "render/intersection_renderer.h"
#include "screens/screen.h"
#include "state/intersection_session.h"
#include "state/strings.h"

namespace hsr::viz {

template <>
class Screen<IntersectionSession> : public ScreenDefaults {
public:
    void frame(const IntersectionSession& s, OrbitCamera& camera) {
        glm::vec3 centre;
        float radius;
        intersection_view_bounds(s.view(), centre, radius);
        frame_bounds(camera, centre, radius);
    }
    void draw_scene(const IntersectionSession& s, SceneFrame& f) const {
        draw_intersection_view(s.view(), s.lesson().scene, f.batches, f.labels);
        f.detail = tr("intersection.caption", {{"volume", volume_title(s.view().input->model.options)}});
        f.covered.push_back(view_legend_rect(f.view_w, f.view_h, intersection_colours::all));
    }
    void draw_panels(const IntersectionSession& s, PanelFrame& f) const {
        view_legend(f.view_w, f.view_h, intersection_colours::all);  // what the volumes' colours say, in the view
        intersection_state_panel(s, f.layout);
    }
};

}  // namespace hsr::viz
