// SPDX-License-Identifier: MIT
// Undo and redo for a session's edits: the states before each edit, and those undone. A drag is many small moves;
// recorded with `same_drag` they make one step.
#pragma once

#include <utility>
#include <vector>

namespace hsr::viz {

template <class State>
class EditHistory {
public:
    // Call before an edit with the state it changes.
    void record(const State& before, bool same_drag = false) {
        if (!(same_drag && !undo_.empty())) undo_.push_back(before);
        redo_.clear();
    }
    // Swap `current` with the state before the last edit (undo) or after the last undo (redo); false when none.
    bool undo(State& current) { return step(undo_, redo_, current); }
    bool redo(State& current) { return step(redo_, undo_, current); }

private:
    std::vector<State> undo_, redo_;
    static bool step(std::vector<State>& from, std::vector<State>& to, State& current) {
        if (from.empty()) return false;
        to.push_back(std::move(current));
        current = std::move(from.back());
        from.pop_back();
        return true;
    }
};

}  // namespace hsr::viz
