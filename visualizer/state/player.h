// SPDX-License-Identifier: MIT
// The player: an append-only event log pulled lazily from the machine, a cursor, and keyframes of the view.
//
// The view shown at cursor k is the fold of events [0, k) over the initial view. Stepping back never rewinds the
// algorithm: seek(k) restores the nearest keyframe at or before k and folds forward from there. Keyframes are
// taken while folding forward, spaced so that their bytes stay a fixed fraction of the log's (a large view is
// keyframed less often), which bounds both the memory and the folding a seek has to do.
//
// View must be copyable, `reduce(View&, const Event&)` must fold one event (not "apply": std::apply would win by ADL), and `approx_bytes(const View&)` must
// say roughly how much a copy costs; both are found by argument-dependent lookup.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "core/steps.h"
#include "state/event_log.h"
#include "state/long_work.h"

namespace hsr::viz {

struct PlayerOptions {
    std::size_t max_events = 50'000'000;  // a guard for the window; machines have their own step bounds
    // and no more than this many bytes of events (looked at every 4,096 events): a BSP traversal of a million city
    // triangles filled 5 GB of log before the event count stopped it
    std::size_t max_log_bytes = std::size_t(2) << 30;
    // Keyframes every max(min_keyframe_interval, approx_bytes(view) / keyframe_bytes_per_event) events: a seek
    // folds at most that many events, and keyframes cost about keyframe_bytes_per_event per event of the log.
    std::size_t min_keyframe_interval = 2048;
    std::size_t keyframe_bytes_per_event = 16;
};

template <class Event, class Result, class View>
class Player {
public:
    using Machine = algo::Steps<Event, Result>;

    Player(Machine machine, View initial, PlayerOptions options = {})
        : machine_(std::move(machine)), options_(options), view_(initial) {
        next_keyframe_at_ = keyframe_interval(initial);
        keyframes_.push_back({0, std::move(initial)});
    }

    // ── where we are ──
    [[nodiscard]] std::size_t cursor() const { return cursor_; }
    [[nodiscard]] std::size_t known() const { return log_.size(); }
    [[nodiscard]] bool complete() const { return machine_.done(); }  // every event is in the log
    [[nodiscard]] bool at_end() const { return cursor_ == log_.size() && (complete() || capped()); }
    // The log holds all it may (max_events or max_log_bytes): the run goes on no further in this player.
    [[nodiscard]] bool capped() const { return log_.size() >= options_.max_events || log_full_; }
    [[nodiscard]] const View& view() const { return view_; }
    [[nodiscard]] Event event(std::size_t k) const { return log_.at(k); }
    // The event that made the current view: event(cursor − 1), if any.
    [[nodiscard]] std::optional<Event> last_applied() const {
        return cursor_ == 0 ? std::nullopt : std::optional<Event>(log_.at(cursor_ - 1));
    }
    [[nodiscard]] const Result* result() const { return complete() ? &machine_.result() : nullptr; }
    [[nodiscard]] const EventLog<Event>& log() const { return log_; }
    [[nodiscard]] std::size_t keyframe_count() const { return keyframes_.size(); }
    [[nodiscard]] std::size_t keyframe_bytes() const {
        std::size_t b = 0;
        for (const auto& k : keyframes_) b += approx_bytes(k.view);
        return b;
    }

    // Pulls events until the log holds n (or the machine ends) without moving the cursor: lets a window show a
    // lesson's length up front while a huge run stays lazy beyond n.
    void prefetch(std::size_t n) { ensure_known(n); }

    // ── moving ──
    bool step_forward() {
        if (!ensure_known(cursor_ + 1)) return false;
        fold_to(cursor_ + 1);
        return true;
    }
    bool step_back() {
        if (cursor_ == 0) return false;
        seek(cursor_ - 1);
        return true;
    }
    // Moves forward to just after the next event for which `major(event)` holds (or to the end).
    template <class Pred>
    bool step_forward_until(Pred major) {
        bool moved = false;
        while (step_forward()) {
            moved = true;
            if (major(log_.at(cursor_ - 1))) break;
        }
        return moved;
    }
    // Moves back to just after the previous major event (or to the start).
    template <class Pred>
    bool step_back_until(Pred major) {
        if (cursor_ == 0) return false;
        std::size_t k = cursor_ - 1;
        while (k > 0 && !major(log_.at(k - 1))) --k;
        seek(k);
        return true;
    }
    // The view after events [0, k); k is clamped to the events the machine has.
    void seek(std::size_t k) {
        ensure_known(k);
        k = std::min(k, log_.size());
        if (k == cursor_) return;
        const auto& key = nearest_keyframe(k);
        if (!(cursor_ < k && cursor_ >= key.at)) {  // folding on from here is no cheaper than from the keyframe
            view_ = key.view;
            cursor_ = key.at;
        }
        fold_to(k);
    }
    void seek_end() {
        while (ensure_known(log_.size() + 1)) {
        }
        seek(log_.size());
    }

private:
    struct Keyframe {
        std::size_t at;  // the view after events [0, at)
        View view;
    };

    // Pulls events from the machine until the log holds at least n (or the machine ends). True when it does.
    bool ensure_known(std::size_t n) {
        while (log_.size() < n && !capped()) {
            const Event* e = machine_.next();
            if (!e) {
                log_.shrink_to_fit();  // the log is complete: give back the growth slack
                break;
            }
            log_.push(*e);
            if (log_.size() % 4096 == 0 && log_.bytes() >= options_.max_log_bytes) log_full_ = true;
            LongWork::tick();  // a huge run shows the window busy and can be stopped (Esc) between two events
        }
        return log_.size() >= n;
    }

    const Keyframe& nearest_keyframe(std::size_t k) const {
        auto it = std::upper_bound(keyframes_.begin(), keyframes_.end(), k,
                                   [](std::size_t x, const Keyframe& f) { return x < f.at; });
        return *std::prev(it);
    }

    void fold_to(std::size_t k) {
        while (cursor_ < k) {
            reduce(view_, log_.at(cursor_));
            ++cursor_;
            maybe_keyframe();
            LongWork::tick();
        }
    }

    // The view's size is measured when a keyframe is taken, not after every event: measuring is as slow as the view
    // is large, and per event that made opening a 65,535-polygon BSP lesson quadratic.
    void maybe_keyframe() {
        if (cursor_ <= keyframes_.back().at || cursor_ < next_keyframe_at_) return;
        keyframes_.push_back({cursor_, view_});
        next_keyframe_at_ = cursor_ + keyframe_interval(view_);
    }
    std::size_t keyframe_interval(const View& v) const {
        return std::max(options_.min_keyframe_interval, approx_bytes(v) / options_.keyframe_bytes_per_event);
    }

    Machine machine_;
    PlayerOptions options_;
    EventLog<Event> log_;
    std::vector<Keyframe> keyframes_;  // sorted by `at`; the first is the initial view
    View view_;
    std::size_t cursor_ = 0;
    std::size_t next_keyframe_at_ = 0;  // the next keyframe is taken on reaching this event
    bool log_full_ = false;             // max_log_bytes reached
};

}  // namespace hsr::viz
