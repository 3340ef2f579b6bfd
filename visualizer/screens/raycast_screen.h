// SPDX-License-Identifier: MIT
// Ray casting: the rays leaving the eye through the grid's pixels, and the image they make.
#pragma once

#include "panels/raycast_panels.h"
#include "render/frustum.h"
#include "render/raycast_renderer.h"
#include "screens/screen.h"
#include "state/raycast_session.h"
#include "state/strings.h"

namespace hsr::viz {

template <>
class Screen<RayCastSession> : public ScreenDefaults {
public:
    void frame(const RayCastSession& s, OrbitCamera& camera) const {
        glm::vec3 centre(0);
        float radius = 1;
        scene_bounds(s.scene(), centre, radius);  // the polygons and the eye
        camera.yaw = 0.9f, camera.pitch = 0.35f;  // from the side: the rays leave the eye across the view
        // lifted above the image inset, which holds the view's lower left third (framed in the middle of the whole
        // view, the scene's lower left lay under it)
        frame_in_part(camera, centre, 0.8f * radius, {0, 1, 0.8f});
    }
    void draw_scene(const RayCastSession& s, SceneFrame& f) const {
        draw_raycast_view(s.view(), s.scene(), f.batches, f.labels);
        f.detail = tr("raycast.caption", {{"width", std::to_string(s.lesson().grid.width)}, {"height", std::to_string(s.lesson().grid.height)},
                                          {"acceleration", window_strings().say(algo::term(s.view().acceleration))}});
    }
    void draw_panels(const RayCastSession& s, PanelFrame& f) const {
        raycast_image(s, 0, 0, f.view_w, f.view_h);
        raycast_state_panel(s, f.layout);
    }
};

}  // namespace hsr::viz
