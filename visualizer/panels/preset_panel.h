// SPDX-License-Identifier: MIT
// P: the presets of the lesson's algorithm over the view: its extreme cases (keys 1 … 9, or click) with what each
// promises, a random scene from a seed (0), and the way back to the lesson (B).
#pragma once

#include <string>
#include <vector>

#include "panels/lesson_panels.h"
#include "panels/ui_actions.h"
#include "state/presets.h"

namespace hsr::viz {

void preset_panel(const std::vector<Preset>& presets, bool has_random, std::uint32_t next_seed, bool away_from_lesson,
                  const PanelLayout& layout, UiActions& out);

}  // namespace hsr::viz
