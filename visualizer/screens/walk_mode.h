// SPDX-License-Identifier: MIT
// Walking through the scene (W), for the screens that offer it (culling, Hi-Z and portal lessons): the arrows walk
// and turn, a drag in the view looks around, the panel switches stages; every change runs the pipeline again from
// the new eye (state/walkthrough.h) and prints one line on stdout for logs and tests. A screen owns one and hands
// it its keys, drags, scene and panels while it walks.
#pragma once

#include <cmath>
#include <cstdio>
#include <optional>

#include <glm/trigonometric.hpp>

#include "panels/culling_panels.h"
#include "render/culling_renderer.h"
#include "screens/screen.h"
#include "state/strings.h"
#include "state/walkthrough.h"

namespace hsr::viz {

// The camera's whole image in a canvas: a canvas narrower than the image shows all of its width (and more above
// and below), so that what the pipeline renders at the sides stays in the picture.
inline glm::mat4 whole_width(algo::Camera eye, float canvas_aspect) {
    const double wide = eye.aspect / canvas_aspect;
    eye.aspect = canvas_aspect;
    if (wide > 1) {
        if (eye.projection == algo::Projection::perspective) eye.fov_y = 2 * glm::degrees(std::atan(std::tan(glm::radians(eye.fov_y) / 2) * wide));
        else eye.box[2] *= wide, eye.box[3] *= wide;
    }
    return glm::mat4(algo::view_projection(eye));
}

class WalkMode {
public:
    [[nodiscard]] bool walking() const { return walk_.has_value(); }
    // W starts a walk through `scene` with `stages` on (or ends it); the arrows, the switches and the coherence box
    // change it, and the frame is made again when they did.
    void apply(const UiActions& a, const algo::Scene& scene, const std::vector<algo::Stage>& stages, const algo::PipelineOptions& options) {
        if (a.toggle_walk) {
            if (walk_) walk_.reset();
            else walk_.emplace(scene, stages, algo::Viewport{320, 240}, options);
        }
        if (!walk_) return;
        if (a.forward || a.left) walk_->walk(a.forward, a.left);
        if (a.walk_stage && *a.walk_stage >= 0 && std::size_t(*a.walk_stage) < std::size(algo::all_stages)) walk_->toggle(algo::all_stages[*a.walk_stage]);
        if (a.walk_coherent) walk_->set_coherent(*a.walk_coherent);
        const auto before = walk_->frames();
        walk_->frame();
        if (walk_->frames() != before) std::printf("hsrviz: %s\n", walk_->summary().c_str());
    }
    // A drag in the view looks around (true: taken; else the view orbits, as ever).
    bool pointer(const Pointer& p) {
        if (!walk_ || p.right) return false;
        if (p.kind == Pointer::Kind::press) {
            if (p.over_ui) return false;
            dragging_ = true, from_ = {p.x, p.y};
            return true;
        }
        if (!dragging_) return false;
        if (p.kind == Pointer::Kind::move) walk_->look(p.x - from_.x, p.y - from_.y), from_ = {p.x, p.y};
        if (p.kind == Pointer::Kind::release) dragging_ = false;
        return true;
    }
    void draw_scene(SceneFrame& f) const {
        draw_walk_view(*walk_, f.batches);
        f.view_projection = whole_width(walk_->camera(), f.aspect());
        char ms[32];
        std::snprintf(ms, sizeof ms, "%.2f", walk_->frame_ms());
        const auto& kept = walk_->last().kept;
        f.detail = tr("walk.caption", {{"drawn", std::to_string(std::count(kept.begin(), kept.end(), 1))},
                                       {"primitives", std::to_string(walk_->scene().polygons.size())}, {"ms", ms}});
    }
    void draw_panels(PanelFrame& f) const { walk_panel(*walk_, f.layout, f.actions); }

private:
    std::optional<Walkthrough> walk_;
    bool dragging_ = false;
    glm::vec2 from_{0};
};

}  // namespace hsr::viz
