// SPDX-License-Identifier: MIT
#include "state/practice/practice_mode.h"

#include <algorithm>

namespace hsr::viz::practice {

const Topic& PracticeMode::chosen() const { return topics()[topic_]; }

const TopicScore& PracticeMode::score() const {
    static const TopicScore none;
    const auto at = scores_.find(chosen().id);
    return at == scores_.end() ? none : at->second;
}

void PracticeMode::choose(std::size_t topic, Level level, std::uint64_t series) {
    topic_ = std::min(topic, topics().size() - 1);
    level_ = std::clamp(level, Level::easy, Level::hard);
    series_ = series;
    next_index_ = 0;
}

const Exercise& PracticeMode::next() {
    current = exercise(chosen(), series_, next_index_++, level_);
    right.reset();
    given.clear();
    typed.clear();
    return *current;
}

std::optional<bool> PracticeMode::answer(const std::string& reply) {
    if (!waiting()) return std::nullopt;
    right = grade(*current, reply);
    given = reply;
    TopicScore& s = scores_[current->topic];
    ++s.answered;
    if (*right) {
        ++s.right;
        s.best_streak = std::max(s.best_streak, ++s.streak);
    } else {
        s.streak = 0;
    }
    return right;
}

void PracticeMode::type(char c) {
    if (!waiting() || !current->choices.empty()) return;
    if (c == '\b') {
        if (!typed.empty()) typed.pop_back();
    } else if (((c >= '0' && c <= '9') || c == '.' || c == ',' || (c == '-' && typed.empty())) && typed.size() < 24) {
        typed += c;
    }
}

std::optional<std::size_t> PracticeMode::hold() const {
    if (!waiting()) return std::nullopt;
    return current->hold_at.value_or(current->deciding_step);
}

std::map<std::string, PracticeRecord> PracticeMode::records() const {
    std::map<std::string, PracticeRecord> r;
    for (const auto& [topic, s] : scores_) r[topic] = {s.answered, s.right, s.best_streak};
    return r;
}

void PracticeMode::restore(const std::map<std::string, PracticeRecord>& records) {
    for (const auto& [topic, r] : records) scores_[topic] = {r.answered, r.right, 0, r.best_streak};
}

std::optional<std::size_t> PracticeMode::topic_of(std::string_view algorithm) {
    for (std::size_t k = 0; k < topics().size(); ++k)
        for (std::string_view a : topics()[k].algorithms)
            if (a == algorithm) return k;
    return std::nullopt;
}

}  // namespace hsr::viz::practice
