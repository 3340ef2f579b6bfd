// SPDX-License-Identifier: MIT
// Back-face culling: each face with its normal and the view vector of the test, from the scene's camera.
#pragma once

#include "panels/backface_panels.h"
#include "render/backface_renderer.h"
#include "screens/screen.h"
#include "state/backface_session.h"
#include "state/strings.h"

namespace hsr::viz {

template <>
class Screen<BackfaceSession> : public ScreenDefaults {
public:
    void frame(const BackfaceSession& s, OrbitCamera& camera) const {
        glm::vec3 centre(0);
        float radius = 1;
        backface_view_bounds(s.view(), centre, radius);
        frame_left_of_side_box(camera, centre, radius, faces_box_share);  // the faces' table is in the view's right part
    }
    void draw_scene(const BackfaceSession& s, SceneFrame& f) const {
        draw_backface_view(s.view(), s.lesson().scene, f.batches, f.labels);
        f.detail = tr("backface.caption", {{"test", window_strings().say(algo::term(s.view().test))}});
    }
    void draw_panels(const BackfaceSession& s, PanelFrame& f) const {
        const bool table_in_view = side_box_fits(f.view_w, faces_box_share);
        if (table_in_view) backface_faces_box(s, f.view_w, f.view_h);
        backface_state_panel(s, table_in_view, f.layout);
    }
};

}  // namespace hsr::viz
