// SPDX-License-Identifier: MIT
// Draws a clipping view in world space: the clip volume as the camera's frustum (or box), the plane in focus as a
// translucent face, every primitive faint as given and bold where it is visible, and the working state of the
// primitive being clipped. Reads the view and the scene; changes neither.
#pragma once

#include <string>
#include <vector>

#include "render/label.h"
#include "render/line_batch.h"
#include "scene/scene.h"
#include "state/clip_view.h"

namespace hsr::viz {


// A step in motion: the view before it, and how far (0 … 1) the picture has moved from there to the current view.
struct Tween {
    const ClipView* before = nullptr;
    float t = 1;
};

// The working segment's ends (and Liang–Barsky's t_enter, t_leave) slide from `tween.before` to `view`; the rest
// of the picture shows `view`. Stepping back tweens the same way, from the later view to the earlier one.
// `outcode_regions` (key V) adds the 27 regions of the outcodes, each labelled with its code.
void draw_clip_view(const ClipView& view, const algo::Scene& scene, LineBatches& batches, std::vector<Label>& labels,
                    Tween tween = {}, bool outcode_regions = false);

// The points the viewer's camera frames: the clip volume's corners, the eye and the primitives near them.
std::vector<glm::vec3> clip_view_points(const ClipView& view, const algo::Scene& scene);

}  // namespace hsr::viz
