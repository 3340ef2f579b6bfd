// SPDX-License-Identifier: MIT
// The classroom in the window: the chapter showing (its title and narration in the chosen language) above the
// lesson's summary, and the open question at the foot of the panel column, where it hides nothing of the view it
// asks about, with a button per choice (keys 1 to 9), then the verdict with the machine's own sentence, and the
// score.
#pragma once

#include "panels/lesson_panels.h"
#include "state/classroom.h"
#include "state/course.h"

namespace hsr::viz {

// Replaces the lesson panel when the lesson has chapters.
void chapter_lesson_panel(const Session& s, const Classroom& room, const std::string& detail, const PanelLayout& layout);
// The column's last box: the open question (out.answer on a click) or the last verdict; at the lesson's end, the
// end card (the score, what the lesson showed, the next lesson of the course, `next`, to open).
// The language for the keys' hint: "de", or "de; this lesson speaks en" when the lesson lacks the chosen one.
std::string language_hint(const Classroom& room);
void question_panel(const Session& s, const Classroom& room, const CourseLesson* next, const PanelLayout& layout,
                    UiActions& out);

}  // namespace hsr::viz
