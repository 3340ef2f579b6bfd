#include "state/lesson_check.h"

#include "analysis/expect_check.h"
#include "state/families.h"
#include "state/lesson_script.h"

namespace hsr::viz {

CheckResult check_file(const std::string& path) {
    CheckResult r;
    try {
        const Lesson lesson = load_lesson(path);
        const auto session = make_session(lesson);
        session->prefetch(prefetch_events);
        r.events = session->known();
        if (!session->complete()) r.problems.push_back(path + ": the machine did not finish within " + std::to_string(prefetch_events) + " events");
        const LessonScript script(*session);
        r.chapters = lesson.chapters.size();
        for (const Chapter& c : lesson.chapters) r.questions += c.question.has_value();
        for (std::string& p : script.problems(lesson, event_kinds(lesson))) r.problems.push_back(std::move(p));
        // A scene's own [expect] tables, against the machines (a teacher's scene states what it should show)
        for (const analysis::ExpectOutcome& o : analysis::check_expectations(lesson.scene))
            if (!o.passed) r.problems.push_back(lesson.scene.source + ":" + std::to_string(o.line) + ": " + o.what + ": " + o.detail);
    } catch (const std::exception& e) {
        r.problems.push_back(e.what());
    }
    return r;
}

}  // namespace hsr::viz
