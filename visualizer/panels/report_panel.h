// SPDX-License-Identifier: MIT
// R: error against run time for the family of the algorithm being played, over the view (state/presets.h), and
// while it is measured, a progress bar with a Cancel button.
#pragma once

#include <optional>
#include <vector>

#include "analysis/measurement.h"
#include "panels/lesson_panels.h"
#include "panels/ui_actions.h"

namespace hsr::viz {

// `measuring`: the share of the measurement done while it runs (nullopt when it does not). Sets
// out.cancel_measurement when Cancel is pressed.
void report_panel(const std::vector<analysis::Measurement>& rows, std::optional<float> measuring, const PanelLayout& layout,
                  UiActions& out);

}  // namespace hsr::viz
