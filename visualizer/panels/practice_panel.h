// SPDX-License-Identifier: MIT
// X: practice, in the column's question box (it hides nothing of the scene it asks about): the topic, level and
// series (a teacher hands out "series 1234"), the exercise's question with its choices (keys 1 … 9) or the number
// being typed (Enter answers), then the verdict with the machine's deciding step, the score and the streak.
#pragma once

#include "panels/lesson_panels.h"
#include "panels/ui_actions.h"
#include "state/practice/practice_mode.h"

namespace hsr::viz {

void practice_panel(const practice::PracticeMode& mode, const PanelLayout& layout, UiActions& out);

}  // namespace hsr::viz
