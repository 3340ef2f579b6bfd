// SPDX-License-Identifier: MIT
// The window's practice (X): the topic, level and series the student chose, the exercise on screen, the number
// being typed, and the score and streak per topic. Headless and tested; the window plays the exercise's scene with
// its algorithm (lesson_play.cpp), holds the player before the deciding event until the student has answered, and
// shows all this in the column's question box (panels/practice_panel.cpp).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "state/practice/practice.h"
#include "state/window_settings.h"

namespace hsr::viz::practice {

struct TopicScore {
    int answered = 0, right = 0;
    int streak = 0, best_streak = 0;  // right answers in a row
};

class PracticeMode {
public:
    bool open = false;                   // the practice box shows (X)
    std::optional<Exercise> current;     // the exercise being played
    std::optional<bool> right;           // once answered: the verdict
    std::string given;                   // the answer given
    std::string typed;                   // a number being typed (digits, '.', ',', '-'; Backspace)

    std::size_t topic() const { return topic_; }
    Level level() const { return level_; }
    std::uint64_t series() const { return series_; }
    std::uint64_t next_index() const { return next_index_; }
    const Topic& chosen() const;
    const TopicScore& score() const;     // of the chosen topic

    // Another topic, level or series: the next exercise is the first of the series (a teacher's "series 1234").
    void choose(std::size_t topic, Level level, std::uint64_t series);
    // Draws the next exercise of the series and forgets the last verdict.
    const Exercise& next();
    // Grades the reply to the exercise waiting for one, and scores it; nothing when none waits.
    std::optional<bool> answer(const std::string& reply);
    // A key for the number being typed: a digit, '.', ',', '-', or '\b' (Backspace); ignored for choices.
    void type(char c);
    bool waiting() const { return current && !right; }
    // Where a move forward stops while the exercise waits for its answer: before its deciding event.
    std::optional<std::size_t> hold() const;

    // The scores as the window keeps them between runs (the streak starts again: its best is kept).
    std::map<std::string, PracticeRecord> records() const;
    void restore(const std::map<std::string, PracticeRecord>& records);

    // The topic whose exercises play this algorithm (the lesson's), if there is one.
    static std::optional<std::size_t> topic_of(std::string_view algorithm);

private:
    std::size_t topic_ = 0;
    Level level_ = Level::easy;
    std::uint64_t series_ = 1, next_index_ = 0;
    std::map<std::string, TopicScore, std::less<>> scores_;
};

}  // namespace hsr::viz::practice
