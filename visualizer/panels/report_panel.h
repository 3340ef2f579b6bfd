// R: error against run time for the family of the algorithm being played, over the view (state/family_report.h).
#pragma once

#include <vector>

#include "analysis/measurement.h"
#include "panels/lesson_panels.h"

namespace hsr::viz {

void report_panel(const std::vector<analysis::Measurement>& rows, const PanelLayout& layout);

}  // namespace hsr::viz
