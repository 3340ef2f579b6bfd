// SPDX-License-Identifier: MIT
// What DisplayBSP has painted so far, seen from the eye, for the image beside the traversal.
//  - A 3D scene: the polygons drawn so far, in the traversal's order, each over what is there, through the scene's
//    camera (its eye where the view's eye is).
//  - A 2D floor plan: the first-person strip of the classic BSP applets. The eye stands in the plan looking along
//    the camera's heading; each wall (segment) is stood up around the eye's height and
//    painted in the traversal's order, so a near wall covers a far one only because it is painted later, as the
//    painter's algorithm promises.
#pragma once

#include "raster/image.h"
#include "raster/screen_polygon.h"
#include "scene/scene.h"
#include "state/bsp_view.h"

namespace hsr::viz {

// Front to back, each polygon covers only the pixels still empty.
// `scene` is the lesson's scene as edited (its colours, its camera with the eye and heading); `size` the image's.
algo::Image bsp_painted_so_far(const BspView& view, const algo::Scene& scene, algo::Viewport size);

// The camera the first-person strip of a 2D plan is seen through: at the eye, looking along the plan camera's
// heading (target − eye, in z = 0), up along +z, with the scene camera's field of view across the strip.
algo::Camera strip_camera(const algo::Camera& plan, double aspect);

// The larger side of the box around the plan's (or scene's) polygons.
double plan_size(const BspView& view);

}  // namespace hsr::viz
