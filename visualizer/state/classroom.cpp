// SPDX-License-Identifier: MIT
#include "state/classroom.h"

#include <algorithm>

namespace hsr::viz {

void Classroom::attach(const Session& s) {
    script_.emplace(s);
    const Lesson& l = s.lesson();
    if (languages_ != l.languages) {  // a new lesson: its languages, its default first; answers start afresh
        languages_ = l.languages;
        follow_choice();
        answers_.clear(), right_ = 0;
    }
    questions_ = int(std::count_if(l.chapters.begin(), l.chapters.end(), [](const Chapter& c) { return c.question.has_value(); }));
}

int Classroom::questions() const { return questions_; }

int Classroom::answered() const {
    return int(std::count_if(answers_.begin(), answers_.end(), [](const auto& a) { return !a.second.revealed; }));
}

std::optional<std::size_t> Classroom::chapter(const Session& s) const {
    return script_ ? script_->chapter_at(s.cursor()) : std::nullopt;
}

bool Classroom::crossed_a_pause(const Session& s, std::size_t before) const { return first_pause_crossed(s, before).has_value(); }

std::optional<std::size_t> Classroom::first_pause_crossed(const Session& s, std::size_t before) const {
    if (!script_ || s.cursor() <= before) return std::nullopt;
    const auto& chapters = s.lesson().chapters;
    std::optional<std::size_t> first;
    for (std::size_t c = 0; c < chapters.size(); ++c) {
        const auto& start = script_->places()[c].starts;
        if (start && *start > before && *start <= s.cursor() && (chapters[c].pause || chapters[c].question) && (!first || *start < *first))
            first = *start;
    }
    return first;
}

const Question* Classroom::open_question(const Session& s) const {
    const auto c = chapter(s);
    if (!c || answers_.contains(*c)) return nullptr;
    const auto& ch = s.lesson().chapters[*c];
    const auto& held = script_->places()[*c].held;
    return ch.question && held && s.cursor() <= *held ? &*ch.question : nullptr;
}

std::optional<std::size_t> Classroom::hold(std::size_t from) const {
    if (!script_) return std::nullopt;
    std::optional<std::size_t> first;
    for (std::size_t c = 0; c < script_->places().size(); ++c) {
        const auto& held = script_->places()[c].held;
        if (!held || answers_.contains(c)) continue;
        if (*held >= from && (!first || *held < *first)) first = *held;
    }
    return first;
}

std::optional<std::size_t> Classroom::stop_forward(const Session& s, std::size_t before, bool stepping, bool questions_hold) const {
    if (s.cursor() <= before) return std::nullopt;
    std::optional<std::size_t> stop;
    if (stepping) stop = first_pause_crossed(s, before);
    if (questions_hold)
        if (const auto h = hold(before); h && *h < s.cursor() && (!stop || *h < *stop)) stop = h;
    return stop;
}

void Classroom::close_revealed(const Session& s) {
    if (!script_) return;
    for (std::size_t c = 0; c < script_->places().size(); ++c) {
        const ChapterPlace& p = script_->places()[c];
        if (p.held && *p.held < s.cursor() && !answers_.contains(c) && s.lesson().chapters[c].question)
            answers_[c] = Verdict{false, p.answer, p.because, true};
    }
}

std::optional<Verdict> Classroom::answer(Session& s, const std::string& given) {
    const auto c = chapter(s);
    if (!c || !open_question(s)) return std::nullopt;
    const ChapterPlace& place = script_->places()[*c];
    const Verdict v = judge(place, given);
    answers_[*c] = v;
    right_ += v.right;
    // the next events decide: show the one that answered, but never move past the start of a later chapter (its
    // words and its question come first; the verdict gives the deciding event's sentence meanwhile)
    std::size_t to = *place.answered;
    if (const auto next = script_->next_chapter(s.cursor())) to = std::min(to, *script_->places()[*next].starts - 1);
    s.seek(std::max(to, s.cursor()));
    return v;
}

std::optional<Verdict> Classroom::verdict(const Session& s) const {
    // the chapter showing, once answered (or its deciding event shown first)
    const auto c = chapter(s);
    if (!c || !answers_.contains(*c)) return std::nullopt;
    return answers_.at(*c);
}

void Classroom::next_language(const std::vector<std::string>& chrome) {
    std::vector<std::string> all = languages_;
    for (const std::string& l : chrome)
        if (std::find(all.begin(), all.end(), l) == all.end()) all.push_back(l);
    const std::string& now = chosen_.empty() ? language_ : chosen_;
    const auto it = std::find(all.begin(), all.end(), now);
    chosen_ = (it == all.end() || it + 1 == all.end()) ? all.front() : *(it + 1);
    follow_choice();
}

void Classroom::choose_language(const std::string& language) {
    chosen_ = language;
    follow_choice();
}

void Classroom::follow_choice() {
    const bool spoken = std::find(languages_.begin(), languages_.end(), chosen_) != languages_.end();
    language_ = spoken ? chosen_ : languages_.front();
}

void Classroom::next_chapter(Session& s) const {
    if (!script_) return;
    if (const auto c = script_->next_chapter(s.cursor())) s.seek(*script_->places()[*c].starts);
}

void Classroom::previous_chapter(Session& s) const {
    if (!script_) return;
    if (const auto c = script_->previous_chapter(s.cursor())) s.seek(*script_->places()[*c].starts);
}

}  // namespace hsr::viz
