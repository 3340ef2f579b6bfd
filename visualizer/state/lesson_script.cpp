// SPDX-License-Identifier: MIT
#include "state/lesson_script.h"

#include <algorithm>

namespace hsr::viz {

LessonScript::LessonScript(const Session& s) {
    const auto& chapters = s.lesson().chapters;
    places_.resize(chapters.size());
    const std::size_t n = s.known();
    std::vector<nlohmann::json> events;  // parsed once, only as far as a chapter needs
    const auto event = [&](std::size_t k) -> const nlohmann::json& {
        while (events.size() <= k) events.push_back(nlohmann::json::parse(s.event_line(events.size())));
        return events[k];
    };
    for (std::size_t c = 0; c < chapters.size(); ++c) {
        const Chapter& ch = chapters[c];
        ChapterPlace& p = places_[c];
        if (ch.step) {
            if (*ch.step <= n) p.starts = *ch.step;
        } else {
            for (std::size_t k = 0; k < n && !p.starts; ++k)
                if (fits(event(k), *ch.when)) p.starts = k + 1;
        }
        if (!p.starts || !ch.question) continue;
        for (std::size_t k = *p.starts; k < n; ++k)
            if (fits(event(k), ch.question->answer_event)) {
                p.answered = k + 1;
                p.answer = event(k).contains(ch.question->field) ? value_text(event(k)[ch.question->field]) : "";
                // said as the choice that names it ("#0" for polygon 0), the way the question and the picture say it
                for (const std::string& choice : ch.question->choices)
                    if (choice != p.answer && choice_is(choice, p.answer)) p.answer = choice;
                if (!event(k).contains(ch.question->field))
                    for (const auto& [key, value] : event(k).items())
                        if (key != "kind" && key != "text") p.fields.push_back(key);
                p.because = event(k).value("text", "");
                // the question waits for its answer where it is asked: a move forward (a step, play, End, the
                // scrub bar) does not leave the chapter's first step while it is open. Events between it and the
                // deciding one often give the answer away (a narration's "accepted", a table's row, a highlighted
                // pseudocode line); the answer then steps on to the deciding event.
                p.held = *p.starts;
                break;
            }
    }
}

std::optional<std::size_t> LessonScript::chapter_at(std::size_t step) const {
    std::optional<std::size_t> best;
    for (std::size_t c = 0; c < places_.size(); ++c)
        if (places_[c].starts && *places_[c].starts <= step && (!best || *places_[*best].starts <= *places_[c].starts)) best = c;
    return best;
}

std::optional<std::size_t> LessonScript::next_chapter(std::size_t step) const {
    std::optional<std::size_t> best;
    for (std::size_t c = 0; c < places_.size(); ++c)
        if (places_[c].starts && *places_[c].starts > step && (!best || *places_[c].starts < *places_[*best].starts)) best = c;
    return best;
}

std::optional<std::size_t> LessonScript::previous_chapter(std::size_t step) const {
    std::optional<std::size_t> best;
    for (std::size_t c = 0; c < places_.size(); ++c)
        if (places_[c].starts && *places_[c].starts < step && (!best || *places_[c].starts > *places_[*best].starts)) best = c;
    return best;
}

std::vector<std::string> LessonScript::problems(const Lesson& lesson, const std::vector<std::string>& kinds) const {
    std::vector<std::string> out;
    const auto known = [&](const std::string& k) { return std::find(kinds.begin(), kinds.end(), k) != kinds.end(); };
    std::string all;
    for (const auto& k : kinds) all += (all.empty() ? "" : ", ") + k;
    for (std::size_t c = 0; c < places_.size(); ++c) {
        const Chapter& ch = lesson.chapters[c];
        const std::string at = lesson.source + ":" + std::to_string(ch.line) + ": chapters[" + std::to_string(c) + "]";
        if (ch.when && !known(ch.when->kind))
            out.push_back(at + ".when: the machine never tells \"" + ch.when->kind + "\"; it tells " + all);
        else if (!places_[c].starts)
            out.push_back(at + ": never starts (no event fits it, or the step is past the end)");
        if (!ch.question) continue;
        const std::string q = lesson.source + ":" + std::to_string(ch.question->line) + ": chapters[" + std::to_string(c) + "].question";
        if (!known(ch.question->answer_event.kind))
            out.push_back(q + ".event: the machine never tells \"" + ch.question->answer_event.kind + "\"");
        else if (places_[c].starts && !places_[c].answered)
            out.push_back(q + ": no event after the chapter starts answers it");
        else if (places_[c].answered && !places_[c].fields.empty()) {
            std::string fields;
            for (const std::string& f : places_[c].fields) fields += (fields.empty() ? "" : ", ") + f;
            out.push_back(q + ".field: the event \"" + ch.question->answer_event.kind + "\" has no field \"" + ch.question->field +
                          "\"; it has " + fields);
        } else if (places_[c].answered && !ch.question->choices.empty() &&
                 std::none_of(ch.question->choices.begin(), ch.question->choices.end(),
                              [&](const std::string& choice) { return choice_is(choice, places_[c].answer); }))
            out.push_back(q + ".choices: the machine's answer \"" + places_[c].answer + "\" is not among them");
    }
    return out;
}

// "#0" rather than "0": the keys 1, 2, 3 then do not read as the numbers 0, 1, 2 they choose.
bool choice_is(const std::string& choice, const std::string& answer) {
    // a numbered thing named as the picture names it: "#3" for polygon 3, "P1" for point 1
    return choice == answer || (choice.size() > 1 && (choice[0] == '#' || choice[0] == 'P') && choice.substr(1) == answer);
}

Verdict judge(const ChapterPlace& place, const std::string& given) { return {choice_is(given, place.answer), place.answer, place.because}; }

}  // namespace hsr::viz
