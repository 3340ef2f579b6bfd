// SPDX-License-Identifier: MIT
// The two painter's algorithms as images: a BSP tree traversed back to front from the camera's eye, and Newell's
// depth sort, each painting whole polygons over what is there. Shared by `hsrviz render` and the report.
#pragma once

#include "bsp/bsp_tree.h"
#include "core/work_meter.h"
#include "raster/image.h"
#include "raster/screen_polygon.h"
#include "depth_sort/depth_sort.h"
#include "scene/scene.h"

namespace hsr::analysis {

struct BspPainting {
    algo::Image image{0, 0};
    algo::BspTree tree;
    double build_ms = 0;  // the build alone; the traversal and painting come after
};
// With a meter, the long work tells how far it has come and can be stopped (algo::WorkStopped).
BspPainting paint_bsp(const algo::Scene& scene, algo::SplitterRule splitter, algo::Viewport vp, algo::WorkMeter* meter = nullptr);

struct DepthSortPainting {
    algo::Image image{0, 0};
    algo::DepthSortResult sorted;
    double sort_ms = 0;  // the sort alone
};
DepthSortPainting paint_depth_sort(const algo::Scene& scene, algo::Viewport vp, algo::WorkMeter* meter = nullptr);

inline constexpr algo::Color background{26, 28, 33};

}  // namespace hsr::analysis
