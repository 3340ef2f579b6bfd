// SPDX-License-Identifier: MIT
// The 3D view of a culling lesson, from above and behind the camera (a god's-eye view): the camera's frustum, the
// primitives kept solid and those left out faint, the hierarchy's boxes coloured by what happened to them
// (outside orange-red, inside bluish green, partly inside yellow, too small grey, occluded reddish purple, visible sky
// blue: the Okabe–Ito colours, told apart by colour-blind eyes; the lessons name them so), and the
// occluders with the rays of their occlusion frusta.
#pragma once

#include <vector>

#include "render/label.h"
#include "render/line_batch.h"
#include "state/culling_session.h"
#include "state/walkthrough.h"

namespace hsr::viz {

void draw_culling_view(const CullingView& view, LineBatches& batches, std::vector<Label>& labels);
void culling_view_bounds(const CullingView& view, glm::vec3& centre, float& radius);

// Walking (W): the primitives the walk's last frame drew, solid, as the walker's eye sees them.
void draw_walk_view(const Walkthrough& walk, LineBatches& out);

}  // namespace hsr::viz
