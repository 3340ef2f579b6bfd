// SPDX-License-Identifier: MIT
// A lesson's chapters against the events of its machine: where each chapter starts, which chapter is showing at a
// step, and what each question's answer is — read from the machine's own events, never from a key in the file.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "state/session.h"

namespace hsr::viz {

struct ChapterPlace {
    std::optional<std::size_t> starts;   // the step after its event (the event has just been shown); none: never
    std::optional<std::size_t> answered; // question: the step after the event that answers it
    std::optional<std::size_t> held;     // question: where a move forward stops while it is open (the chapter's
                                         // first step, where it is asked: it waits for its answer there)
    std::string answer;                  // the answer's field, as text
    std::string because;                 // the answering event's sentence
    std::vector<std::string> fields;     // the answering event's fields, when it lacks the question's field
};

class LessonScript {
public:
    // Looks through the events the session has pulled (prefetch first for a whole lesson).
    explicit LessonScript(const Session& session);
    const std::vector<ChapterPlace>& places() const { return places_; }
    // The chapter showing at a step: the last one started at or before it.
    std::optional<std::size_t> chapter_at(std::size_t step) const;
    std::optional<std::size_t> next_chapter(std::size_t step) const;
    std::optional<std::size_t> previous_chapter(std::size_t step) const;
    // What is wrong with the chapters against this machine ("" when nothing): a chapter that never starts, a question
    // never answered, an answer not among the choices, an event kind the machine never tells.
    std::vector<std::string> problems(const Lesson& lesson, const std::vector<std::string>& kinds) const;

private:
    std::vector<ChapterPlace> places_;
};

struct Verdict {
    bool right;
    std::string answer, because;
    bool revealed = false;  // the deciding event was shown before an answer was given: no score
};
// Whether a question's choice names the machine's answer: as the machine tells it ("0"), or as the picture labels a
// polygon ("#0").
bool choice_is(const std::string& choice, const std::string& answer);
Verdict judge(const ChapterPlace& place, const std::string& given);

}  // namespace hsr::viz
