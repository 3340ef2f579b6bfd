// SPDX-License-Identifier: MIT
// A lesson being played, whatever its algorithm: what the timeline, narration and pseudocode panels and the
// keyboard need. Each family (clipping, BSP, …) derives a PlayerSession with its own events, view and tables.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "state/lesson.h"
#include "state/player.h"
#include "state/pseudocode.h"
#include "state/trace.h"

namespace hsr::viz {

// How many events a window pulls up front, so that its scrub bar shows a lesson's whole length while a huge run
// stays lazy beyond it.
inline constexpr std::size_t prefetch_events = 100'000;

class Session {
public:
    virtual ~Session() = default;
    const Lesson& lesson() const { return lesson_; }

    virtual std::size_t cursor() const = 0;
    virtual std::size_t known() const = 0;
    virtual bool complete() const = 0;
    virtual bool at_end() const = 0;
    virtual bool capped() const = 0;  // the window keeps no more of this run (its event or memory cap)

    virtual void step() = 0;  // to the next major event
    virtual void step_back() = 0;
    virtual void micro_step() = 0;  // one event
    virtual void micro_step_back() = 0;
    virtual void seek(std::size_t k) = 0;
    virtual void seek_end() = 0;
    virtual void prefetch(std::size_t n) = 0;

    virtual std::string sentence(std::size_t k) const = 0;  // describe(event k), in English (traces, tests, the CLI)
    // The same sentence in the language the window speaks (window_strings()), where the family's machine says it
    // as a template; else the English.
    virtual std::string spoken(std::size_t k) const { return sentence(k); }
    virtual std::string event_line(std::size_t k) const = 0;  // event k as its trace writes it (JSON)
    std::string narration() const { return cursor() == 0 ? std::string() : spoken(cursor() - 1); }  // the window's language
    virtual std::span<const std::string_view> pseudocode() const = 0;
    virtual int current_line() const = 0;  // of pseudocode(), −1 at the start

protected:
    explicit Session(Lesson lesson) : lesson_(std::move(lesson)) {}

private:
    Lesson lesson_;
};

// A lesson's machine and the view it starts from: what a session plays, and what a trace drains. Each family's
// session makes it in one place, its static `machine(const Lesson&)`.
template <class Event, class Result, class View>
struct Run {
    algo::Steps<Event, Result> machine;
    View initial;
};

// The player-backed part every family shares; a family says how to describe an event, which pseudocode line it
// belongs to and whether it is a Step.
template <class Event, class Result, class View>
class PlayerSession : public Session {
public:
    using EventType = Event;
    using ViewType = View;
    using RunType = Run<Event, Result, View>;
    using PlayerType = Player<Event, Result, View>;
    PlayerType& player() { return player_; }
    const PlayerType& player() const { return player_; }
    const View& view() const { return player_.view(); }

    std::size_t cursor() const override { return player_.cursor(); }
    std::size_t known() const override { return player_.known(); }
    bool complete() const override { return player_.complete(); }
    bool at_end() const override { return player_.at_end(); }
    bool capped() const override { return player_.capped(); }
    void step() override { player_.step_forward_until([this](const Event& e) { return is_major(e); }); }
    void step_back() override { player_.step_back_until([this](const Event& e) { return is_major(e); }); }
    void micro_step() override { player_.step_forward(); }
    void micro_step_back() override { player_.step_back(); }
    void seek(std::size_t k) override { player_.seek(k); }
    void seek_end() override { player_.seek_end(); }
    void prefetch(std::size_t n) override { player_.prefetch(n); }
    std::string sentence(std::size_t k) const override { return describe_event(player_.event(k)); }
    std::string spoken(std::size_t k) const override { return speak_event(player_.event(k)); }
    std::string event_line(std::size_t k) const override { return trace_line(k, player_.event(k), sentence(k)); }
    std::span<const std::string_view> pseudocode() const override { return table().text(); }
    int current_line() const override {
        const auto e = player_.last_applied();
        return e ? table().line_of(*e) : -1;
    }

protected:
    PlayerSession(Lesson lesson, PlayerType player) : Session(std::move(lesson)), player_(std::move(player)) {}
    PlayerSession(Lesson lesson, RunType run, PlayerOptions options)
        : PlayerSession(std::move(lesson), PlayerType(std::move(run.machine), std::move(run.initial), options)) {}
    // A rerun with changed inputs: the new machine's player, at the same step where that step still exists.
    void replace_player(PlayerType player) {
        const std::size_t k = player_.cursor();
        player_ = std::move(player);
        player_.prefetch(prefetch_events);
        player_.seek(k);
    }
    virtual std::string describe_event(const Event& e) const = 0;
    virtual std::string speak_event(const Event& e) const { return describe_event(e); }
    // The pseudocode shown now, with the events that light each line and whether they are Steps.
    virtual const Pseudocode<Event>& table() const = 0;
    // A Step stops after a major event, a micro-step after any; an event no line names is a Step.
    virtual bool is_major(const Event& e) const { return table().is_major(e).value_or(true); }

private:
    PlayerType player_;
};

}  // namespace hsr::viz
