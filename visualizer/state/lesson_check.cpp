// SPDX-License-Identifier: MIT
#include "state/lesson_check.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <new>
#include <set>

#include "analysis/expect_check.h"
#include "raster/screen_polygon.h"
#include "state/families.h"
#include "state/glyphs.h"
#include "state/lesson_script.h"

namespace hsr::viz {
namespace {

// Every text the window shows of a lesson, with the field it comes from.
std::vector<std::pair<std::string, std::string>> lesson_texts(const Lesson& l) {
    std::vector<std::pair<std::string, std::string>> texts;
    // a field given in one language is named as the file most likely wrote it: title = "…"
    const auto add = [&](const std::string& field, const Texts& by_language) {
        for (const auto& [language, text] : by_language) texts.emplace_back(by_language.size() == 1 ? field : field + "." + language, text);
    };
    add("title", l.titles);
    add("summary", l.summaries);
    for (std::size_t k = 0; k < l.chapters.size(); ++k) {
        const Chapter& c = l.chapters[k];
        const std::string at = "chapters[" + std::to_string(k) + "]";
        add(at + ".title", c.titles);
        for (const auto& [language, text] : c.narration) texts.emplace_back(at + ".narration." + language, text);
        if (!c.question) continue;
        for (const auto& [language, text] : c.question->ask) texts.emplace_back(at + ".question.ask." + language, text);
        for (const std::string& choice : c.question->choices) texts.emplace_back(at + ".question.choices", choice);
    }
    return texts;
}

// The camera's fields checked against each other (target ≠ eye, up not along the view, far > near): one removed, its
// default may contradict another.
const std::set<std::string> tied_camera_fields{"camera.eye", "camera.target", "camera.up", "camera.near", "camera.far"};

// Every problem that loading the file meets, not only the first: after each, what it names is removed and the file
// read again (at most 20, and never twice the same field: a field that is missing once removed stops it). A later
// problem may follow from an earlier one, as a compiler's do.
std::vector<std::string> load_problems(const std::string& path) {
    std::vector<std::string> out;
    try {
        algo::TomlReader reader(path);
        std::set<std::string> fields, reported;  // as the reader names them; as the file does, with their tables
        std::map<std::string, std::vector<std::size_t>> removed;  // by array ("polygons"): the elements removed, as first numbered
        for (int k = 0; k < 20; ++k) {
            try {
                read_lesson(reader, std::nullopt);
                return out;
            } catch (const algo::LoadError& e) {
                // The field as the file numbers it: polygons[1] after polygons[0] was removed is the file's polygons[2]
                std::string field = e.field;
                if (const std::size_t bracket = field.find('['); bracket != std::string::npos) {
                    const std::string array = field.substr(0, bracket);
                    std::size_t i = std::strtoul(field.c_str() + bracket + 1, nullptr, 10);
                    std::vector<std::size_t>& gone = removed[array];
                    for (const std::size_t r : gone) i += r <= i;
                    field = array + "[" + std::to_string(i) + field.substr(field.find(']', bracket));
                    gone.insert(std::upper_bound(gone.begin(), gone.end(), i), i);
                }
                // A problem the removals made is not the file's (issue 53, item 10): a scene with its only polygon
                // removed has "nothing in it", a field removed is "missing", a camera without its eye has its target
                // "equal to the eye". After the first, a problem of the whole file, of a field already removed or of
                // one tied to a removed one ends the list.
                if (k > 0 && (field.empty() || reported.contains(field))) return out;
                out.push_back(algo::LoadError(e.file, e.line, e.column, field, e.message).what());
                // camera.eye[0] removed leaves camera.eye "not an array of 3": the arrays holding it are tied to it
                for (std::string f = field; !f.empty(); f = f.back() == ']' ? f.substr(0, f.rfind('[')) : "") {
                    reported.insert(f);
                    if (tied_camera_fields.contains(f)) reported.insert(tied_camera_fields.begin(), tied_camera_fields.end());
                }
                // (an unknown algorithm removed would read the lesson as a scene: the first problem is all there is)
                if (e.file != path || e.field.empty() || e.field == "algorithm" || !fields.insert(e.field).second || !reader.forget(e.field))
                    return out;
            }
        }
    } catch (const std::exception& e) {  // the file itself: not there, not text, not TOML
        out.push_back(e.what());
    }
    return out;
}

}  // namespace

CheckResult check_file(const std::string& path) {
    CheckResult r;
    if (std::vector<std::string> problems = load_problems(path); !problems.empty()) {
        r.problems = std::move(problems);
        return r;
    }
    try {
        const Lesson lesson = load_lesson(path);
        const auto session = make_session(lesson);
        session->prefetch(prefetch_events);
        r.events = session->known();
        if (!session->complete()) r.problems.push_back(path + ": the machine did not finish within " + std::to_string(prefetch_events) + " events");
        const LessonScript script(*session);
        r.chapters = lesson.chapters.size();
        for (const auto& [field, text] : lesson_texts(lesson))
            for (const char32_t c : glyphs_missing(text))
                r.warnings.push_back(path + ": " + field + ": " + glyph_name(c) + " is not in the window's font (the window draws � instead)");
        for (const Chapter& c : lesson.chapters) r.questions += c.question.has_value();
        for (const std::string& note : lesson.scene.notes) r.warnings.push_back(note);
        for (const std::string& p : algo::polygons_not_convex(lesson.scene))
            r.warnings.push_back(p + " (the clippers take it; the hidden-surface algorithms and `render` refuse it)");
        for (std::string& p : script.problems(lesson, event_kinds(lesson))) r.problems.push_back(std::move(p));
        // A scene's own [expect] tables, against the machines (a teacher's scene states what it should show)
        for (const analysis::ExpectOutcome& o : analysis::check_expectations(lesson.scene))
            if (!o.passed) r.problems.push_back(lesson.scene.source + ":" + std::to_string(o.line) + ": " + o.what + ": " + o.detail);
    } catch (const std::bad_alloc&) {
        r.problems.push_back(path + ": out of memory: the lesson needs more than this machine (or its limits) allow");
    } catch (const std::exception& e) {
        r.problems.push_back(e.what());
    }
    return r;
}

}  // namespace hsr::viz
