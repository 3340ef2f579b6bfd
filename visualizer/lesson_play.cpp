// SPDX-License-Identifier: MIT
#include "lesson_play.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <new>

#include "platform.h"
#include "scene/input_file.h"
#include "scene/toml_reader.h"
#include "state/output_folder.h"
#include "scene/save_scene.h"
#include "state/long_work.h"
#include "state/strings.h"
#include "state/trace.h"

namespace hsr::viz {
namespace {

// An exercise's title in every language the window speaks.
std::map<std::string, std::string> titles(const practice::Exercise& e) {
    std::map<std::string, std::string> out;
    const Strings& words = window_strings();
    for (const std::string& language : words.languages())
        out[language] = words.text_in(language, "practice.lesson_title",
                                      {{"topic", e.topic}, {"series", std::to_string(e.series)}, {"number", std::to_string(e.index + 1)}});
    return out;
}

std::string seconds_said(const algo::WorkMeter& meter) {  // "3.1 s"
    char b[32];
    std::snprintf(b, sizeof b, "%.1f s", meter.seconds());
    return b;
}

}  // namespace

void LessonPlay::load(const AppOptions& o) {
    // A reload stays at its step where it still exists, also through a failed reload (a file saved half-written).
    const std::size_t keep = session() ? session()->cursor() : place_before_error.value_or(0);
    const bool fresh = !session() && !place_before_error;
    if (path.empty()) home = path = o.lesson_path, algorithm = o.algorithm;
    const std::vector<std::string> watched = watch.files();
    watch.watch({path});
    algo::WorkMeter meter = work_meter("opening " + std::filesystem::path(path).filename().string());
    try {
        LongWork in_place(meter);  // gone before the catch
        const Lesson lesson = load_lesson(path, algorithm);
        presets = extreme_presets(lesson.algorithm, data_dir() + "/assets/scenes/extreme");
        if (session() && session()->lesson().algorithm.machine.index() != lesson.algorithm.machine.index())
            cancel_report(), report.clear();
        std::error_code ec;
        if (lesson.scene.source != path && std::filesystem::is_regular_file(lesson.scene.source, ec))
            watch.watch({path, lesson.scene.source});
        family.emplace(make_session(lesson));
        session()->prefetch(prefetch_events);  // the scrub bar shows a lesson's whole length
        classroom.attach(*session());
        error.clear();
        opening_stopped = false;
        // A lesson that plays but whose chapters cannot work as written (a typo in an event's name, a question
        // nothing answers) says so, as `hsrviz check` would: the teacher sees it before the class does.
        if (const LessonScript* script = classroom.script())
            for (const std::string& problem : script->problems(lesson, event_kinds(lesson))) tell(problem);
        for (const std::string& note : lesson.scene.notes) tell(note);  // faces of no area left out
        frame_bounds(camera, glm::vec3(0), 1);
        with_family_screen([&](auto& s, auto& screen) { screen.frame(s, camera); });
        std::size_t start = keep;
        if (fresh)  // a lesson opened anew starts where its opening chapter does, if it has one
            if (const LessonScript* script = classroom.script())
                for (std::size_t k = 0; k < lesson.chapters.size() && k < script->places().size(); ++k)
                    if (lesson.chapters[k].opens && script->places()[k].starts) {
                        start = *script->places()[k].starts;
                        break;
                    }
        session()->seek(std::min(start, session()->known()));
        place_before_error.reset();
        meter.finish();
    } catch (const algo::WorkStopped&) {  // Esc: the window is the teacher's again, and F5 tries once more
        failed_to_load("opening " + path + " was stopped (" + stopped_by + ") after " + seconds_said(meter) + ", at " +
                           algo::whole_number(meter.progress().done) + " machine steps",
                       watched, path);
        opening_stopped = true;
        if (!fresh) place_before_error = keep;
    } catch (const algo::LoadError& e) {  // a bad file shows its error instead of the scene
        failed_to_load(e.what(), watched, e.file);
    } catch (const std::bad_alloc&) {
        failed_to_load(path + ": out of memory: the lesson needs more than this machine (or its limits) allow", watched, path);
    } catch (const std::exception& e) {
        failed_to_load(e.what(), watched, path);
    }
}

algo::WorkMeter LessonPlay::work_meter(const std::string& what) {
    stop_work = false;
    // the window draws a frame every 0.2 s while it works (Esc is read there), the first after 0.3 s: short work
    // shows nothing
    algo::WorkMeter meter(show_work, &stop_work, 0.3, 0.2);
    meter.stage(what, "machine steps", 0);
    return meter;
}

void LessonPlay::failed_to_load(const std::string& why, std::vector<std::string> watched, const std::string& at_fault) {
    if (session()) place_before_error = session()->cursor();
    family.reset();
    error = algo::printable(why, 2000);
    opening_stopped = false;
    // Still watched: the files watched before (the scene of a lesson that loaded) and the file at fault, so fixing
    // either reloads by itself.
    watched.push_back(path);
    watched.push_back(at_fault);
    watch.watch(watched);
    std::fprintf(stderr, "hsrviz: %s\n", error.c_str());
}

void LessonPlay::choose_preset(const UiActions& a, const AppOptions& o) {
    if (a.back_to_lesson) {
        path = home, algorithm = home == o.lesson_path ? o.algorithm : std::nullopt;
    } else if (a.preset && *a.preset >= 0 && std::size_t(*a.preset) < presets.size()) {
        if (session()) algorithm = std::string(session()->lesson().algorithm.id);
        path = presets[std::size_t(*a.preset)].file;
    } else if (a.random_scene && session()) {
        const bool two_d = with_family_screen([](auto& s, auto& screen) { return screen.two_d(s); });
        const auto toml = random_scene_toml(session()->lesson().algorithm, two_d, next_seed);
        if (!toml) return;
        algorithm = std::string(session()->lesson().algorithm.id);
        const std::string folder = output_folder("hsrviz-export");
        if (!make_folder(folder)) return;
        path = folder + "/random-" + *algorithm + "-seed" + std::to_string(next_seed++) + ".toml";
        std::ofstream(path) << *toml;
    } else {
        return;
    }
    show_presets = false;
    place_before_error.reset();
    family.reset();  // a new scene starts at its first step
    load(o);
    tell("playing " + path + " with " + algorithm.value_or("the lesson's algorithm"),
         algorithm ? tr("notes.playing_with", {{"file", path}, {"algorithm", *algorithm}}) : tr("notes.playing", {{"file", path}}));
}

void LessonPlay::toggle_practice(const AppOptions& o) {
    practice.open = !practice.open;
    if (practice.open) {
        show_presets = show_menu = show_report = false;
        if (!practice.current && session())  // the first time: the topic of the lesson playing, if it has one
            if (const auto topic = practice::PracticeMode::topic_of(session()->lesson().algorithm.id))
                practice.choose(*topic, practice.level(), practice.series());
        if (!practice.waiting()) return play_exercise(o);
        path = practice_scene, algorithm = practice.current->algorithm;  // the exercise left unanswered
    } else {
        path = home, algorithm = home == o.lesson_path ? o.algorithm : std::nullopt;
    }
    place_before_error.reset();
    family.reset();
    load(o);
}

void LessonPlay::play_exercise(const AppOptions& o) {
    const practice::Exercise* e = nullptr;
    try {
        e = &practice.next();
    } catch (const std::exception& failure) {  // a maker that never found a scene: a bug, said, not a crash
        tell(std::string("practice: ") + failure.what());
        return;
    }
    const std::string folder = output_folder("hsrviz-export");
    // the exercise's scene, and a lesson beside it naming the algorithm and (culling) the stages
    const std::string name = "practice-" + e->topic + "-series" + std::to_string(e->series) + "-" + std::to_string(e->index + 1);
    const std::string scene_file = folder + "/" + name + ".toml", file = folder + "/" + name + "-lesson.toml";
    if (!make_folder(folder) || !(std::ofstream(scene_file) << algo::scene_toml(e->scene) << std::flush) ||
        !(std::ofstream(file) << practice::lesson_toml(*e, name + ".toml", titles(*e)) << std::flush)) {
        tell("practice: could not write " + file);
        return;
    }
    practice_scene = path = file;
    algorithm = e->algorithm;
    place_before_error.reset();
    family.reset();  // the exercise starts at its first step
    classroom.restart();
    load(o);
    // open where the question is asked: the picture it is about, every event before the one that decides it (Left
    // and Home step back through them)
    if (const auto hold = practice.hold(); hold && session()) session()->seek(*hold);
    std::printf("hsrviz: practice %s, series %llu, exercise %llu: %s\n", e->topic.c_str(), (unsigned long long)e->series,
                (unsigned long long)(e->index + 1), e->question.c_str());
}

bool LessonPlay::practice_input(const UiActions& a, const AppOptions& o) {
    if (a.practice_choice) {
        practice.choose(a.practice_choice->topic, practice::Level(a.practice_choice->level), a.practice_choice->series);
        play_exercise(o);
        return true;
    }
    if (!practice.waiting()) {
        if (a.practice_next || a.enter) {
            play_exercise(o);
            return true;
        }
        return false;
    }
    const practice::Exercise& e = *practice.current;
    std::optional<std::string> reply = a.answer;
    if (a.digit) {
        if (e.choices.empty()) practice.type(char('0' + *a.digit));
        else if (*a.digit >= 1 && std::size_t(*a.digit) <= e.choices.size()) reply = e.choices[std::size_t(*a.digit - 1)];
    }
    if (a.typed) practice.type(*a.typed);
    if (a.enter && e.choices.empty() && !practice.typed.empty()) reply = practice.typed;
    if (reply) {
        const bool right = practice.answer(*reply).value_or(false);
        std::printf("hsrviz: practice answered \"%s\": %s, the machine says \"%s\" at step %zu\n", reply->c_str(),
                    right ? "right" : "wrong", e.answer.c_str(), e.deciding_step + 1);
        if (session() && path == practice_scene) session()->seek(e.deciding_step + 1);  // the deciding event, shown
        playback.playing = false;
    }
    return a.digit || a.typed || a.enter || a.answer;
}

void LessonPlay::switch_lesson(int step, const AppOptions& o) {
    const std::vector<std::string> lessons = shipped_lessons();
    if (lessons.empty()) return;
    const std::string now = std::filesystem::path(home).filename().string();
    auto at = std::find_if(lessons.begin(), lessons.end(), [&](const std::string& l) { return std::filesystem::path(l).filename() == now; });
    std::ptrdiff_t k = at == lessons.end() ? (step > 0 ? -1 : std::ptrdiff_t(lessons.size())) : at - lessons.begin();
    k = std::clamp<std::ptrdiff_t>(k + step, 0, std::ptrdiff_t(lessons.size()) - 1);
    open_lesson(lessons[std::size_t(k)], o);
}

void LessonPlay::open_lesson(const std::string& lesson, const AppOptions& o) {
    home = path = lesson, algorithm.reset();
    practice.open = false;  // its exercise stays, unanswered, for X to come back to
    place_before_error.reset();
    family.reset();  // a lesson starts at its first step, with a fresh score and no report of another family
    classroom.restart();
    cancel_report();
    report.clear();
    show_presets = show_report = show_menu = false;
    playback.playing = false;
    second_view = false;
    load(o);
    std::printf("hsrviz: lesson %s\n", path.c_str());  // the lesson box and the title say it in the window
}

const CourseLesson* LessonPlay::next_in_course() const {
    const std::string now = std::filesystem::path(home).filename().string();
    for (std::size_t k = 0; k + 1 < course.size(); ++k)
        if (course[k].file == now) return &course[k + 1];
    return nullptr;
}

void LessonPlay::toggle_report(const std::string& scenes_dir) {
    show_report = !show_report;
    if (!show_report) return cancel_report();
    if (!session() || !report.empty() || measuring.running()) return;
    const algo::AlgorithmInfo playing = session()->lesson().algorithm;
    measuring.start([playing, scenes_dir](analysis::Progress& p) { return family_report(playing, scenes_dir, &p); }, can_start_threads());
}

void LessonPlay::collect_report() {
    std::optional<BackgroundMeasurement::Outcome> done = measuring.take();
    if (!done) return;
    if (!done->error.empty())
        return done->cancelled ? tell("measurement cancelled", tr("notes.cancelled"))
                               : tell("could not measure: " + done->error, tr("notes.not_measured", {{"error", done->error}}));
    report = std::move(done->rows);
    tell("measured " + std::to_string(report.size()) + " rows of error against run time" +
             (session() ? " for " + std::string(session()->lesson().algorithm.id) : std::string()),
         tr("notes.measured", {{"rows", std::to_string(report.size())}}));
}

void LessonPlay::cancel_report() {
    if (!measuring.running()) return;
    measuring.stop();  // a cancel is seen before the next timed run: a moment at most
    collect_report();
}

void LessonPlay::tell(const std::string& text, const std::string& shown) {
    std::printf("hsrviz: %s\n", algo::printable(text, 2000).c_str());
    std::fflush(stdout);  // seen at once by whoever reads the terminal or a log (a watched reload, a test)
    toasts.say(algo::printable(shown.empty() ? text : shown, 2000), seconds_now());
}

void LessonPlay::save_edited(const algo::Scene& scene) {
    const std::string folder = output_folder("hsrviz-export");
    const std::string file = folder + "/" + std::filesystem::path(path).stem().string() + "-edited.toml";
    const bool ok = make_folder(folder) && static_cast<bool>(std::ofstream(file) << algo::scene_toml(scene) << std::flush);
    tell((ok ? "saved the edited scene to " : "could not write ") + file, tr(ok ? "notes.saved" : "notes.not_written", {{"file", file}}));
    if (ok) offer_download(file);
}

// In a screen's drive mode the arrows move the eye (and the machine's whole run is shown); in a walk they walk,
// leaving the lesson where it stands and its question hidden; else they step.
UiActions LessonPlay::arrows_as_the_screen_takes_them(const UiActions& keyed) {
    UiActions a = keyed;
    bool drives = false, walking = false;
    if (session()) with_family_screen([&](auto& s, auto& screen) { drives = screen.drives(s, second_view), walking = screen.walking(s); });
    if ((drives || walking) && !show_menu) {
        a.step = a.step_back = a.micro_step = a.micro_step_back = false;
        if (!walking) a.to_end = a.to_end || a.forward || a.left;
        if (walking) a.digit.reset(), a.answer.reset();
    } else {
        a.forward = a.left = 0;
    }
    return a;
}

bool LessonPlay::around_the_lesson(const UiActions& a, double dt, const AppOptions& o) {
    if (a.reload || watch.changed(dt)) {
        load(o);
        tell(error.empty() ? "reloaded " + path : "could not reload " + path + " (its error is shown)",
             tr(error.empty() ? "notes.reloaded" : "notes.not_reloaded", {{"file", path}}));
    }
    if (course.empty()) course = load_course();
    if (a.toggle_menu) {
        show_menu = !show_menu;
        const std::string now = std::filesystem::path(home).filename().string();
        for (std::size_t k = 0; k < course.size(); ++k)
            if (course[k].file == now) menu_cursor = k;  // the menu opens on the lesson playing
    }
    if (a.open_lesson) return open_lesson(*a.open_lesson, o), true;
    if (show_menu) {  // the menu takes ↑ ↓ and Enter, and the stepping keys do not move the lesson behind it
        if (a.up_down && !course.empty())
            menu_cursor = std::size_t(std::clamp<long>(long(menu_cursor) + a.up_down, 0, long(course.size()) - 1));
        if (a.enter && menu_cursor < course.size()) return open_lesson(course[menu_cursor].path, o), true;
        if (a.close_overlays) show_menu = false;
        return true;
    }
    if (a.toggle_practice) toggle_practice(o);
    if (practice.open && practice_input(a, o)) return true;  // its keys are its own while it shows
    if (a.toggle_presets) show_presets = !show_presets;
    if (a.toggle_report) toggle_report(data_dir() + "/assets/scenes");
    if (a.cancel_measurement) cancel_report();
    collect_report();
    if (show_presets) {  // the presets take the number keys while they show: 1 … 9 a case, 0 a random scene
        UiActions pick = a;
        if (a.digit && *a.digit >= 1) pick.preset = *a.digit - 1;
        if (a.digit && *a.digit == 0) pick.random_scene = true;
        choose_preset(pick, o);
        if (show_presets && a.digit) return true;
    } else if (a.preset || a.random_scene || a.back_to_lesson) {
        choose_preset(a, o);
    }
    if (a.next_lesson) switch_lesson(a.next_lesson, o);
    return false;
}

void LessonPlay::classroom_and_window_keys(Session& p, const UiActions& a) {
    // a number answers the open question (and does nothing else)
    std::optional<std::string> answer = a.answer;
    if (a.digit)
        if (const Question* q = classroom.open_question(p); q && *a.digit >= 1 && std::size_t(*a.digit) <= q->choices.size())
            answer = q->choices[std::size_t(*a.digit - 1)];
    if (answer) {
        if (const auto v = classroom.answer(p, *answer))
            std::printf("hsrviz: answered \"%s\": %s, the machine says \"%s\"\n", answer->c_str(), v->right ? "right" : "wrong", v->answer.c_str());
        playback.playing = false;
    }
    if (a.next_chapter) {
        if (classroom.open_question(p) && classroom.script()->next_chapter(p.cursor())) tell("the open question was left unanswered (PageDown)", tr("notes.question_skipped"));
        classroom.next_chapter(p), playback.playing = false;
    }
    if (a.previous_chapter) classroom.previous_chapter(p), playback.playing = false;
    if (a.next_language) classroom.next_language(window_strings().languages());
    if (a.toggle_keys) show_keys = !show_keys;
    side += a.column_wider ? 40.f : a.column_narrower ? -40.f : 0.f;
    if (a.scale_step) scale = std::clamp(scale * (a.scale_step > 0 ? 1.1f : 1 / 1.1f), 0.5f, 4.0f);
    if (a.scale_reset) scale = first_scale;
    if (a.export_all) export_pending = true;
    if (a.close_overlays) {
        if (show_report) cancel_report();
        show_keys = show_presets = show_report = show_menu = false;
    }
    if (a.toggle_3d) second_view = !second_view;
}

void LessonPlay::move(Session& p, const UiActions& a, double dt) {
    if (a.speed) playback.speed = *a.speed;
    const std::size_t cursor = p.cursor();
    const bool waiting = questions_hold && classroom.hold(cursor) == cursor;  // a question waits for its answer here
    if (a.toggle_play) playback.playing = !playback.playing && !p.at_end() && !waiting;
    if (a.step) p.step();
    if (a.step_back) p.step_back();
    if (a.micro_step) p.micro_step();
    if (a.micro_step_back) p.micro_step_back();
    if (a.to_start) p.seek(0);
    if (a.to_end) p.seek_end();
    if (a.seek) p.seek(*a.seek);
    if (a.step || a.step_back || a.micro_step || a.micro_step_back || a.to_start || a.to_end || a.seek) playback.playing = false;
    if (playback.playing) {
        playback.since_step += dt;
        if (playback.since_step >= 1.0 / playback.speed) {
            playback.since_step = 0;
            p.step();
            if (p.at_end()) playback.playing = false;
        }
    }
    hold_where_asked(p, cursor, a.step || a.micro_step || playback.playing);
}

void LessonPlay::hold_where_asked(Session& p, std::size_t from, bool stepping_forward) {
    // a step forward stops where a chapter pauses, so that its question is asked before the events answer it,
    // and no move forward (a step, play, End, the scrub bar) leaves the step where an open question is asked
    if (const auto stop = classroom.stop_forward(p, from, stepping_forward, questions_hold)) {
        p.seek(*stop);
        playback.playing = false;
    }
    // nor, in practice, the event that decides the exercise before it is answered
    if (path == practice_scene)
        if (const auto hold = practice.hold(); hold && p.cursor() > *hold) {
            p.seek(*hold);
            playback.playing = false;
        }
}

void LessonPlay::update(const UiActions& keyed, double dt, const AppOptions& o) {
    const UiActions a = arrows_as_the_screen_takes_them(keyed);
    if (around_the_lesson(a, dt, o) || !session()) return;
    Session& p = *session();
    classroom_and_window_keys(p, a);
    // Long work (End on a run of millions of events, an edit that reruns a huge machine) shows the window busy, and
    // Esc stops it between two events: the lesson stays where the work got to.
    std::size_t cursor = p.cursor();
    algo::WorkMeter meter = work_meter("running " + std::string(p.lesson().algorithm.id));
    try {
        LongWork in_place(meter);  // gone before the catch: what follows it must not tick a stopped meter
        // the family's own edits (a moved eye or vertex, a new segment or triangle, undo, the depth format): the
        // machine reruns, and the classroom follows the new events
        with_family_screen([&](auto& s, auto& screen) {
            if (screen.apply(s, a)) classroom.attach(p);
            if (a.save_scene)
                if (const auto scene = screen.edited_scene(s)) save_edited(*scene);
        });
        const bool may_move = a.toggle_play || a.step || a.step_back || a.micro_step || a.micro_step_back ||
                              a.to_start || a.to_end || a.seek || playback.playing;
        if (animate && may_move) with_family_screen([](auto& s, auto& screen) { screen.before_step(s); });
        cursor = p.cursor();
        move(p, a, dt);
        meter.finish();
    } catch (const algo::WorkStopped&) {
        playback.playing = false;
        classroom.attach(p);  // an edit's rerun may have stopped before the classroom followed it
        tell("stopped (" + stopped_by + ") after " + seconds_said(meter) + ", at step " + std::to_string(p.cursor()) + " of " +
                 std::to_string(p.known()) + " known so far",
             tr("notes.stopped", {{"by", stopped_by}, {"time", seconds_said(meter)}, {"step", std::to_string(p.cursor())},
                                  {"known", std::to_string(p.known())}}));
    }
    classroom.close_revealed(p);
    with_family_screen([&](auto& s, auto& screen) { screen.after_step(s, p.cursor() != cursor, dt); });
}

}  // namespace hsr::viz
