// SPDX-License-Identifier: MIT
// F1: every key of the window, over the view.
#pragma once

#include "panels/lesson_panels.h"

namespace hsr::viz {

void keys_panel(const PanelLayout& layout);

}  // namespace hsr::viz
