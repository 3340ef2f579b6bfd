// A clipping lesson being played: the lesson, its machine behind a player, and what the panels ask of it.
#pragma once

#include <string>
#include <vector>

#include "clipping/clip_scene.h"
#include "state/clip_view.h"
#include "state/lesson.h"
#include "state/player.h"

namespace hsr::viz {

using ClipPlayer = Player<algo::ClipEvent, std::vector<algo::PrimitiveClip>, ClipView>;

class ClipSession {
public:
    explicit ClipSession(Lesson lesson, PlayerOptions options = {});

    const Lesson& lesson() const { return lesson_; }
    algo::ClipAlgorithm algorithm() const { return algorithm_; }
    algo::ClipSpace space() const { return player_.view().space; }
    ClipPlayer& player() { return player_; }
    const ClipPlayer& player() const { return player_; }

    // Step = to the next major event; micro-step = one event.
    void step() { player_.step_forward_until(is_major_event); }
    void step_back() { player_.step_back_until(is_major_event); }
    // The sentence of the event that made the current view ("" at the start).
    std::string narration() const;
    // The pseudocode line of the current event (−1 at the start).
    int current_line() const;

private:
    static bool is_major_event(const algo::ClipEvent& e);
    Lesson lesson_;
    algo::ClipAlgorithm algorithm_;
    ClipPlayer player_;
};

}  // namespace hsr::viz
