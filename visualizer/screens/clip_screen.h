// SPDX-License-Identifier: MIT
// Clipping: the clip volume in 3D with the primitive being cut; a step slides from the picture before it.
#pragma once

#include "panels/clip_panels.h"
#include "render/clip_renderer.h"
#include "screens/screen.h"
#include "state/clip_session.h"
#include "state/strings.h"

namespace hsr::viz {

template <>
class Screen<ClipSession> : public ScreenDefaults {
public:
    void frame(const ClipSession& s, OrbitCamera& camera) {
        // a sphere round the view volume, the eye and the primitives near them (a polygon beside the volume was cut
        // off under the panels when only the volume was framed)
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (const glm::vec3& p : clip_view_points(s.view(), s.lesson().scene)) lo = glm::min(lo, p), hi = glm::max(hi, p);
        frame_bounds(camera, (lo + hi) * 0.5f, std::max(0.5f, glm::length(hi - lo) * 0.5f));
        before_.reset(), shown_.reset(), tween_ = 1;
    }
    void draw_scene(const ClipSession& s, SceneFrame& f) const {
        draw_clip_view(s.view(), s.lesson().scene, f.batches, f.labels, {before_ ? &*before_ : nullptr, float(tween_)},
                       f.second_view);
        f.detail = tr(s.space() == algo::ClipSpace::homogeneous ? "clipping.detail_clip_space" : "clipping.detail_cube");
        if (s.algorithm() == algo::ClipAlgorithm::cohen_sutherland)
            f.detail += " · " + tr(f.second_view ? "clipping.regions_shown" : "clipping.regions");
    }
    void draw_panels(const ClipSession& s, PanelFrame& f) const { clip_state_panel(s, f.layout); }
    void before_step(const ClipSession& s) { shown_ = s.view(); }  // cheap: the view's large parts are shared
    void after_step(const ClipSession&, bool moved, double dt) {
        if (moved && shown_) {  // a step was taken (either way): slide from what was shown
            before_ = std::move(shown_);
            tween_ = 0;
        } else {
            tween_ = std::min(1.0, tween_ + dt / tween_seconds);
        }
        shown_.reset();
    }

private:
    static constexpr double tween_seconds = 0.25;
    std::optional<ClipView> shown_;   // the view before this frame's step
    std::optional<ClipView> before_;  // the view the picture is sliding from
    double tween_ = 1;                // 0 … 1 of the way from before_ to the current view
};

}  // namespace hsr::viz
