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
                if (!event(k).contains(ch.question->field))
                    for (const auto& [key, value] : event(k).items())
                        if (key != "kind" && key != "text") p.fields.push_back(key);
                p.because = event(k).value("text", "");
                p.held = k;
                break;
            }
        if (p.answered && ch.question->reveals)
            for (std::size_t k = *p.starts; k < *p.held; ++k)
                if (event(k).value("kind", "") == *ch.question->reveals) {
                    p.held = k;
                    break;
                }
    }
    // A question is asked in its own chapter: when the event that decides it lies beyond the start of the next
    // chapter, the hold is the chapter's last step (the student answers before the class moves on, and the verdict
    // gives the deciding event's sentence), never a step where another chapter shows.
    for (ChapterPlace& p : places_)
        if (p.held)
            if (const auto next = next_chapter(*p.starts); next && *p.held >= *places_[*next].starts) p.held = *places_[*next].starts - 1;
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
        else if (ch.question->reveals && !known(*ch.question->reveals))
            out.push_back(q + ".reveals: the machine never tells \"" + *ch.question->reveals + "\"");
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
    return choice == answer || (choice.size() > 1 && choice[0] == '#' && choice.substr(1) == answer);
}

Verdict judge(const ChapterPlace& place, const std::string& given) { return {choice_is(given, place.answer), place.answer, place.because}; }

}  // namespace hsr::viz
