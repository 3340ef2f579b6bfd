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
        // the faces' corners and the eye, as large as the part left of the faces' table allows (a sphere round their
        // box left the models a sixth of the view, their face numbers piled on each other)
        std::vector<glm::vec3> points{glm::vec3(s.view().eye)};
        for (const auto& face : s.view().faces)
            for (const algo::Vec3& x : *face.vertices) points.emplace_back(x);
        frame_points_in_part(camera, points, {0, 1 - faces_box_share, 1});
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
