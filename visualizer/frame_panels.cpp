// SPDX-License-Identifier: MIT
#include "frame_panels.h"

#include <optional>
#include <vector>

#include "panels/chapter_panels.h"
#include "panels/keys_panel.h"
#include "panels/lesson_menu.h"
#include "panels/practice_panel.h"
#include "panels/preset_panel.h"
#include "panels/report_panel.h"
#include "panels/toast_panel.h"
#include "state/strings.h"
#include "state/window_settings.h"

namespace hsr::viz {

namespace {

// The lesson's last chapter shows, or its last step: the result comes first in the column.
bool at_last_chapter(const LessonPlay& lp) {
    const Session* s = lp.session();
    if (!s) return false;
    if (s->complete() && s->cursor() >= s->known()) return true;
    const auto c = lp.classroom.chapter(*s);
    return c && *c + 1 == s->lesson().chapters.size();
}

}  // namespace

PanelLayout arrange_frame(LessonPlay& lp, float width, float height) {
    lp.side = clamp_side(lp.side, width);
    // the column and the timeline grow with the type (the column's width is remembered unscaled)
    PanelLayout layout{width, height, clamp_side(lp.side * lp.scale, width), 96 * lp.scale};
    lp.column.arrange(layout.height - layout.bottom, lp.path, at_last_chapter(lp));
    layout.fit = &lp.column;
    return layout;
}

glm::mat4 draw_frame_content(LessonPlay& lp, LineBatches& lines, std::vector<Label>& labels, const PanelLayout& layout,
                             UiActions& actions) {
    const float view_w = layout.width - layout.side, view_h = layout.height - layout.bottom;
    lines.faint.clear();
    lines.bold.clear();
    labels.clear();
    if (!lp.session()) {
        draw_frame_panels(lp, "", 0, 0, layout, actions);
        return lp.camera.view_projection(view_w / view_h);
    }
    // the family's 3D view and caption, drawn in the space left of the panels and above the timeline
    SceneFrame scene{lines, labels, "", std::nullopt, lp.second_view, view_w, view_h, {}, lp.camera.eye()};
    lp.with_family_screen([&](auto& session, auto& screen) { screen.draw_scene(session, scene); });
    const glm::mat4 vp = scene.view_projection.value_or(lp.camera.view_projection(view_w / view_h));
    draw_labels(labels, vp, 0, 0, view_w, view_h, scene.covered);
    draw_frame_panels(lp, scene.detail, view_w, view_h, layout, actions);
    return vp;
}

void draw_frame_panels(LessonPlay& lp, const std::string& detail, float view_w, float view_h, const PanelLayout& layout,
                       UiActions& actions) {
    // the window's own words follow the student's choice (L) where a catalogue has it, even when the lesson's narration
    // does not
    window_strings().use(lp.classroom.window_language());
    if (!lp.session()) {
        error_panel(lp.error + (lp.path != lp.home ? "\n\nB: back to the lesson.  P: the other presets." : ""), lp.opening_stopped, layout,
                    actions);
        if (lp.show_presets) preset_panel(lp.presets, false, lp.next_seed, lp.path != lp.home, layout, actions);
        toast_panel(lp.toasts, seconds_now(), layout);
        return;
    }
    const Session& s = *lp.session();
    // the family's canvases and state panel, then what every lesson has
    PanelFrame panels{view_w, view_h, layout, lp.second_view, lp.animate, actions};
    bool walking = false;  // a walk through the scene (W) needs the column for its stages, not the step-through's boxes
    lp.with_family_screen([&](auto& session, auto& screen) { screen.draw_panels(session, panels), walking = screen.walking(session); });
    if (s.lesson().chapters.empty()) lesson_panel(s, detail, layout);
    else chapter_lesson_panel(s, lp.classroom, detail, layout);
    if (!walking) pseudocode_panel(s, layout);
    if (lp.practice.open && lp.path == lp.practice_scene) practice_panel(lp.practice, layout, actions);
    else if (!walking) question_panel(s, lp.classroom, lp.next_in_course(), layout, actions);
    if (lp.show_report)
        report_panel(lp.report, lp.measuring.running() ? std::optional(lp.measuring.fraction()) : std::nullopt, layout, actions);
    if (lp.show_keys) keys_panel(layout);
    if (lp.show_presets)
        preset_panel(lp.presets, has_random_scene(s.lesson().algorithm), lp.next_seed, lp.path != lp.home, layout, actions);
    if (lp.show_menu) lesson_menu(lp.course, lp.home, lp.menu_cursor, lp.classroom.chosen_language(), layout, actions);
    toast_panel(lp.toasts, seconds_now(), layout);
    if (!walking) narration_panel(s, layout);
    const Question* open = walking ? nullptr : lp.classroom.open_question(s);  // a walk hides the question: no key answers it
    std::vector<TimelineMark> marks;
    if (const LessonScript* script = lp.classroom.script())
        for (std::size_t k = 0; k < script->places().size() && k < s.lesson().chapters.size(); ++k)
            if (const auto at = script->places()[k].starts)
                marks.push_back({*at, s.lesson().chapters[k].question.has_value(),
                                 in_language(s.lesson().chapters[k].titles, lp.classroom.language(), s.lesson().languages)});
    timeline_panel(s, lp.playback, open ? open->choices.size() : 0, s.lesson().chapters.empty() ? "" : language_hint(lp.classroom),
                   marks, layout, actions);
}

}  // namespace hsr::viz
