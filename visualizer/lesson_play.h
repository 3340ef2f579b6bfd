// SPDX-License-Identifier: MIT
// The lesson being played in the window: its session (as its family's type) and screens, the playback, the
// classroom, the presets and the report, and the update that carries out a frame's UiActions.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app.h"
#include "core/work_meter.h"
#include "state/column_fit.h"
#include "panels/ui_actions.h"
#include "render/orbit_camera.h"
#include "screens/screens.h"
#include "state/classroom.h"
#include "state/course.h"
#include "state/toasts.h"
#include "state/file_watch.h"
#include "state/presets.h"
#include "state/background_measurement.h"
#include "state/practice/practice_mode.h"

namespace hsr::viz {

struct LessonPlay {
    std::optional<FamilySession> family;  // the lesson being played, as its family's type
    Screens screens;                      // one per family
    std::string error;                    // why the lesson could not be loaded ("" when it could)
    bool opening_stopped = false;         // the error is that opening was stopped (Esc), not the file
    std::optional<std::size_t> place_before_error;  // the step a failed reload left: the fixed file opens there again
    PlaybackState playback;
    OrbitCamera camera;
    bool animate = true;                  // off for screenshots and recordings: they show each step as it ends
    bool second_view = false;             // V: the family's other view (z-buffer 3D, portals walk-through, culling camera)
    bool questions_hold = true;           // a move forward stops before the event that answers an open question
    Classroom classroom;                  // chapters, questions, language, score
    FileWatch watch;                      // the lesson and scene files: edited on disk, reloaded
    bool show_keys = false;               // F1
    bool export_pending = false;          // E: written after the next frame is drawn
    std::string home;                     // the lesson the window was started with
    std::string path;                     // what plays: the lesson, or a preset scene chosen with P
    std::optional<std::string> algorithm;
    bool show_presets = false;            // P
    bool show_menu = false;               // M: the lesson menu
    std::size_t menu_cursor = 0;          // the lesson the arrow keys are on
    std::vector<CourseLesson> course;     // the shipped lessons, for the menu and the end card
    Toasts toasts;                        // notes of what happened (exported, saved, reloaded, …)
    float side = 500;                     // the panel column's width ([ and ] change it; remembered)
    ColumnFit column;                     // the column's boxes sized to their content
    float scale = 1, first_scale = 1;     // of type and panels (Ctrl+= / Ctrl+−), and as the window started
    bool show_report = false;             // R: error against run time for the algorithm's family
    std::vector<analysis::Measurement> report;  // measured when R first opens it
    BackgroundMeasurement measuring;      // R's measurement while it runs (a progress bar; closing R cancels it)
    std::vector<Preset> presets;          // of the lesson's algorithm
    std::uint32_t next_seed = 1;          // of the next random scene
    practice::PracticeMode practice;      // X: exercises the machine grades, each played in the view
    std::string practice_scene;           // the file of the exercise playing (held before its deciding event)
    // Long work (a lesson opening on a huge scene, End on a long run, an edit that reruns a big machine): the window
    // shows it while it lasts and stops it on Esc (or when it is closed), by setting stop_work and saying why.
    algo::WorkMeter::Teller show_work;
    std::atomic<bool> stop_work{false};
    std::string stopped_by = "Esc";

    Session* session() const { return family ? &**family : nullptr; }
    // f(session, screen) with the family's own types; only while a lesson plays
    template <class F>
    decltype(auto) with_family_screen(F&& f) {
        return with_screen(*family, screens, std::forward<F>(f));
    }

    // (Re)loads `path` (the options' lesson at first), at the same step where it still exists.
    void load(const AppOptions& o);
    // The error shown instead of the scene; the place and the watched files kept for the reload that fixes it.
    void failed_to_load(const std::string& why, std::vector<std::string> watched, const std::string& at_fault);
    // P: play another scene with the lesson's algorithm (an extreme case, a random scene), or go back to the lesson.
    void choose_preset(const UiActions& a, const AppOptions& o);
    // N / Shift+N: the next or previous shipped lesson, from its start (a teacher switching lessons in class).
    void switch_lesson(int step, const AppOptions& o);
    // A lesson chosen in the menu, from its start.
    void open_lesson(const std::string& lesson, const AppOptions& o);
    // X: practice opens on the lesson's topic and plays an exercise, or closes, back to the lesson.
    void toggle_practice(const AppOptions& o);
    // Plays practice's next exercise: its scene, written to the output folder, with its algorithm, from step 0.
    void play_exercise(const AppOptions& o);
    // Practice's keys and clicks while its box shows (choices, the number typed, Enter, another series); true when
    // they were practice's.
    bool practice_input(const UiActions& a, const AppOptions& o);
    // The lesson after the one playing in the course, if there is one.
    const CourseLesson* next_in_course() const;
    // S: the scene as edited, to hsrviz-export/NAME-edited.toml
    void save_edited(const algo::Scene& scene);
    // Says what happened: on the terminal ("hsrviz: …", English, for logs and tests) and for a few seconds in the
    // window, in the student's language where `shown` is given.
    void tell(const std::string& text, const std::string& shown = {});
    // R: opens the report (measuring it off this thread the first time) or closes it (cancelling a measurement).
    void toggle_report(const std::string& scenes_dir);
    // The report's rows, once a measurement started by R is in (said in the window).
    void collect_report();
    // Stops R's measurement, if one runs, saying so.
    void cancel_report();
    // A meter for long work named `what`, shown by the window and stopped by stop_work (reset here).
    algo::WorkMeter work_meter(const std::string& what);
    // One frame's actions and dt seconds of playing: the parts below, in this order.
    void update(const UiActions& a, double dt, const AppOptions& o);

private:
    // The arrows as the family's screen takes them: stepping, driving the eye, or walking.
    UiActions arrows_as_the_screen_takes_them(const UiActions& keyed);
    // What is around the lesson: a reload, the menu, practice, the presets, the report, another lesson. True when
    // the frame's input was theirs (or the lesson changed) and the lesson does not move.
    bool around_the_lesson(const UiActions& a, double dt, const AppOptions& o);
    // The classroom's keys (an answer, a chapter, the language) and the window's (keys, column, type size, export,
    // Esc, V).
    void classroom_and_window_keys(Session& p, const UiActions& a);
    // The player moved: a step, play, Home, End, the scrub bar; then held where a question is asked.
    void move(Session& p, const UiActions& a, double dt);
    // Where a move forward from `from` must stop: a chapter's pause or open question, practice's deciding event.
    void hold_where_asked(Session& p, std::size_t from, bool stepping_forward);
};

}  // namespace hsr::viz
