// SPDX-License-Identifier: MIT
// Back-face culling: each face with its normal and the view vector of the test, from the scene's camera.
#pragma once

#include "panels/backface_panels.h"
#include "panels/state_legend.h"
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
        draw_backface_view(s.view(), f.camera_eye, f.batches, f.labels);
        f.detail = tr("backface.caption", {{"test", window_strings().say(algo::term(s.view().test))}}) + " · " + tr("backface.dim_number");
        f.covered.push_back(view_legend_rect(legend_width(f.view_w), f.view_h, legend(s.view())));
    }
    void draw_panels(const BackfaceSession& s, PanelFrame& f) const {
        const bool table_in_view = side_box_fits(f.view_w, faces_box_share);
        if (table_in_view) backface_faces_box(s, f.view_w, f.view_h);
        view_legend(legend_width(f.view_w), f.view_h, legend(s.view()));  // what the outlines' colours say, left of the table
        backface_state_panel(s, table_in_view, f.layout);
    }

private:
    static float legend_width(float view_w) { return side_box_fits(view_w, faces_box_share) ? view_w * (1 - faces_box_share) : view_w; }
    // the marks the view shows: "culled though seen" only where the ray cast ran
    static std::vector<StateColour> legend(const BackfaceView& v) {
        std::vector<StateColour> shown{backface_colours::kept, backface_colours::under_test, backface_colours::culled};
        if (!v.faces.empty() && v.faces.front().seen) shown.push_back(backface_colours::culled_seen);
        return shown;
    }
};

}  // namespace hsr::viz
