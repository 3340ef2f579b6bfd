// SPDX-License-Identifier: MIT
// Newell's depth sort: the pair R, Q in the canonical view volume, the display list, the screen inset and the
// image painted so far.
#pragma once

#include "panels/depth_sort_panels.h"
#include "render/depth_sort_renderer.h"
#include "screens/screen.h"
#include "state/depth_sort_session.h"
#include "state/strings.h"

namespace hsr::viz {

template <>
class Screen<DepthSortSession> : public ScreenDefaults {
public:
    void frame(const DepthSortSession&, OrbitCamera& camera) {  // the canonical view volume, from the eye's side
        camera.yaw = 0.55f, camera.pitch = 0.35f;
        frame_above_foot_box(camera, glm::vec3(0), 1.45f, 0.38f);  // above the two insets (depth_sort_insets)
        chips_ = {}, painted_for_.reset();
    }
    void draw_scene(const DepthSortSession& s, SceneFrame& f) const {
        draw_depth_sort_view(s.view(), f.batches, f.labels);
        f.detail = tr("depth_sort.detail");
        f.covered = depth_sort_insets(0, 0, f.view_w, f.view_h).covered();
    }
    void draw_panels(const DepthSortSession& s, PanelFrame& f) {
        // repainted only when what is drawn changes (a step, a seek, a reload): the list back to front, then what
        // the display step drew front to back
        std::vector<std::uint32_t> drawn = s.view().drawn;
        drawn.push_back(~0u), drawn.insert(drawn.end(), s.view().front.begin(), s.view().front.end());
        if (painted_for_ != drawn) {
            painted_ = painted_so_far(s.view(), {128, 128});
            painted_for_ = std::move(drawn);
        }
        depth_sort_canvas(s, chips_, painted_, 0, 0, f.view_w, f.view_h, f.animate);
        depth_sort_state_panel(s, f.layout);
    }

private:
    ChipPlaces chips_;
    algo::Image painted_{0, 0};
    std::optional<std::vector<std::uint32_t>> painted_for_;  // the drawn lists painted_ shows
};

}  // namespace hsr::viz
