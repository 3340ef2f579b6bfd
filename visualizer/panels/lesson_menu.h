// SPDX-License-Identifier: MIT
// The lesson menu (M, or the timeline's Lessons button): the course by topic, each lesson with its difficulty and
// what it builds on; the one playing marked, the one the arrow keys are on highlighted. A click, or Enter, opens it.
#pragma once

#include <vector>

#include "panels/lesson_panels.h"
#include "state/course.h"

namespace hsr::viz {

void lesson_menu(const std::vector<CourseLesson>& course, const std::string& playing, std::size_t cursor, const std::string& language,
                 const PanelLayout& layout, UiActions& out);

}  // namespace hsr::viz
