// SPDX-License-Identifier: MIT
// Roberts' hidden lines: the line drawing as the scene's eye sees it, built edge by edge.
#pragma once

#include "panels/roberts_panels.h"
#include "render/roberts_renderer.h"
#include "screens/screen.h"
#include "state/roberts_session.h"
#include "state/strings.h"

namespace hsr::viz {

template <>
class Screen<RobertsSession> : public ScreenDefaults {
public:
    void frame(const RobertsSession&, OrbitCamera&) const {}  // the scene's own eye (draw_scene)
    void draw_scene(const RobertsSession& s, SceneFrame& f) const {
        f.view_projection = roberts_camera(s.lesson().scene, f.aspect());
        draw_roberts_view(s.view(), s.lesson().scene, f.batches, f.labels);
        f.detail = tr("roberts.caption", {{"bodies", std::to_string(s.view().input->bodies.size())}});
    }
    void draw_panels(const RobertsSession& s, PanelFrame& f) const { roberts_state_panel(s, f.layout); }
};

}  // namespace hsr::viz
