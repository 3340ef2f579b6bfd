// SPDX-License-Identifier: MIT
// Draws a back-face culling view: faces kept light, culled faces dark, untested faces faint (the legend's colours); for the
// face just tested, its normal and the view vector from the eye (or the eye-to-plane distance). A face the camera
// (`camera_eye`, not the test's eye) sees from behind has its number dim and in brackets: drawn over the faces in
// front of it, a plain number would seem to name one of them.
#pragma once

#include <vector>

#include "render/label.h"
#include "render/line_batch.h"
#include "scene/scene.h"
#include "state/backface_view.h"

namespace hsr::viz {

void draw_backface_view(const BackfaceView& view, glm::vec3 camera_eye, LineBatches& batches, std::vector<Label>& labels);

}  // namespace hsr::viz
