// SPDX-License-Identifier: MIT
// The classroom side of a lesson being played: which chapter shows, the language, the questions answered and the
// score. Playback pauses where a chapter asks it to (or asks a question); an answer is judged by the machine's own
// event, which the player then steps to so that the student sees it.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "state/lesson_script.h"

namespace hsr::viz {

class Classroom {
public:
    // After a lesson is (re)loaded or its machine reruns.
    void attach(const Session& session);
    // After playback moved from `before` to the session's cursor: true when it crossed the start of a chapter that
    // pauses (or asks a question), so playing should stop there.
    bool crossed_a_pause(const Session& session, std::size_t before) const;
    // The first such start crossed (where a step should stop, so that a question is asked before it is answered).
    std::optional<std::size_t> first_pause_crossed(const Session& session, std::size_t before) const;

    std::optional<std::size_t> chapter(const Session& session) const;  // showing now
    // The question of the chapter showing, if it has one not yet answered and its deciding event is still to come.
    const Question* open_question(const Session& session) const;
    // Where a move forward from step `from` must stop while a question is unanswered: just before the event that
    // answers it (or an earlier one that gives the answer away), so that the student answers before the machine
    // tells. nullopt: nothing holds.
    std::optional<std::size_t> hold(std::size_t from) const;
    // After a move forward from `before` to the session's cursor, where it must stop instead (nullopt: nowhere):
    // a step or play (`stepping`) at the first start of a chapter that pauses or asks; any move (End, the scrub bar
    // too) just before the event that answers an open question, while `questions_hold`.
    std::optional<std::size_t> stop_forward(const Session& session, std::size_t before, bool stepping, bool questions_hold) const;
    // After a move: a question whose deciding event has been shown before it was answered (a chapter skipped, a
    // reload at a later step) is closed; it scores nothing and its verdict says so.
    void close_revealed(const Session& session);
    // Answers the open question with choice `index` (or text); the player steps to the answering event, or to the
    // chapter's last step when a later chapter starts before it.
    std::optional<Verdict> answer(Session& session, const std::string& given);
    std::optional<Verdict> verdict(const Session& session) const;  // of the chapter showing, once answered or revealed
    // L: the next language the window can speak: the lesson's narration languages, then those with a window-word
    // catalogue (`chrome`). The choice is the student's: it outlives the lesson (restart keeps it) and is what the
    // window's own words follow; the narration follows it where the lesson has it, else speaks the lesson's first.
    void next_language(const std::vector<std::string>& chrome = {});
    void choose_language(const std::string& language);  // the choice remembered from the last run
    const std::string& chosen_language() const { return chosen_; }
    // What the window's own words speak: the student's choice, else (none made yet) the narration's language.
    const std::string& window_language() const { return chosen_.empty() ? language_ : chosen_; }
    // Another lesson (or exercise): nothing of this one stays but the student's choice of language.
    void restart() {
        std::string chosen = std::move(chosen_);
        *this = Classroom{};
        chosen_ = std::move(chosen);
    }
    // PageDown / PageUp: to the next or previous chapter's start.
    void next_chapter(Session& session) const;
    void previous_chapter(Session& session) const;

    const std::string& language() const { return language_; }  // the narration's
    int right() const { return right_; }
    int answered() const;  // by the student (not revealed first)
    int questions() const;
    const LessonScript* script() const { return script_ ? &*script_ : nullptr; }

private:
    std::optional<LessonScript> script_;
    std::vector<std::string> languages_{"en"};
    std::string language_ = "en";
    std::string chosen_;  // "" until the student chooses: then the lesson's first
    void follow_choice();
    std::map<std::size_t, Verdict> answers_;  // by chapter
    int right_ = 0, questions_ = 0;
};

}  // namespace hsr::viz
