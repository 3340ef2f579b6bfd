// The report for the algorithm being played (R in the window): its family's rows of `hsrviz report`, measured now
// with the quick settings (small scenes, three repeats), so a student sees error against run time beside the steps.
#pragma once

#include <string>
#include <vector>

#include "analysis/measurement.h"
#include "registry.h"

namespace hsr::viz {

// The family's measurements: clipping for the clippers; the z-buffer for the z-buffer, scan line and z-merge; BSP
// and depth sort (with the ray cast) for those and ray casting; portals; culling for culling and back-face culling.
std::vector<analysis::Measurement> family_report(const algo::AlgorithmInfo& algorithm, const std::string& scenes_dir);

}  // namespace hsr::viz
