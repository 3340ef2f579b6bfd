// SPDX-License-Identifier: MIT
// The perspective transform: the view volume warped into the canonical box, the points and their projectors with it.
#pragma once

#include "panels/perspective_panels.h"
#include "render/perspective_renderer.h"
#include "screens/screen.h"
#include "state/perspective_session.h"
#include "state/strings.h"

namespace hsr::viz {

template <>
class Screen<PerspectiveSession> : public ScreenDefaults {
public:
    void frame(const PerspectiveSession&, OrbitCamera& camera) {  // the unit cube the picture lives in, from the side
        camera.yaw = 0.9f, camera.pitch = 0.3f;
        frame_above_foot_box(camera, glm::vec3(0, 0, 0.15f), 1.55f, points_box_share);  // the points' table is below
    }
    void draw_scene(const PerspectiveSession& s, SceneFrame& f) const {
        draw_perspective_view(s.view(), s.lesson().scene, f.batches, f.labels);
        f.detail = tr("transform.caption");
    }
    void draw_panels(const PerspectiveSession& s, PanelFrame& f) const {
        const bool table_in_view = foot_box_fits(f.view_w);
        if (table_in_view) perspective_points_box(s, f.view_w, f.view_h);
        perspective_state_panel(s, table_in_view, f.layout);
    }
};

}  // namespace hsr::viz
