// SPDX-License-Identifier: MIT
// The window's notes (state/toasts.h), at the top of the view, fading out.
#pragma once

#include "panels/lesson_panels.h"
#include "state/toasts.h"

namespace hsr::viz {

void toast_panel(const Toasts& toasts, double now, const PanelLayout& layout);

}  // namespace hsr::viz
