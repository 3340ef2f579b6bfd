// SPDX-License-Identifier: MIT
// Long work, told and stoppable. A command that drains a machine counts what is done against what there is to do;
// every 64 events the meter looks at the clock and, at most twice a second (or as often as asked), tells how far it has come
// (done, left, an estimate of the time left) to whoever shows it: stderr for the command line, a bar in the window.
// It also looks at a stop flag (set by Ctrl+C or Esc) and then throws WorkStopped, before anything is written: long
// work stops cleanly and leaves no half-made output.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/steps.h"

namespace hsr::algo {

struct WorkStopped : std::runtime_error {
    WorkStopped() : std::runtime_error("stopped before the work was done") {}
};

// 262144 → "262,144" (a count, rounded; negative counts are 0)
std::string whole_number(double x);

struct WorkProgress {
    std::string stage;  // "ray cast", "BSP build", …
    std::string unit;   // what is counted: "rays", "polygons", …
    double done = 0, total = 0;
    double seconds = 0;                   // since the stage started
    std::optional<double> seconds_left;   // a straight-line estimate from the rate since the first look that found something done
    bool finished = false;                // the stage's last word (told only if something was told before)
    [[nodiscard]] std::string sentence() const;  // "ray cast: 120,000 of 262,144 rays (46 %), 3.1 s, about 3.6 s left"
};

class WorkMeter {
public:
    using Teller = std::function<void(const WorkProgress&)>;
    // `stop` may be null (nothing can stop the work); `tell` may be empty (nobody watches, but stop still works).
    // The first tell comes after `first_tell_after_seconds` (short work says nothing), the next ones
    // `tell_every_seconds` apart (the window tells more often than a terminal: its teller is also where Esc is read).
    WorkMeter(Teller tell, const std::atomic<bool>* stop, double first_tell_after_seconds = 1.0, double tell_every_seconds = 0.5);

    void stage(std::string name, std::string unit, double total);  // a new stage starts: its clock, its count
    void set_total(double total) { progress_.total = total; }      // the total grew (a BSP split adds a polygon)
    // Cheap enough for every event: the stop flag is looked at every call (one relaxed load; an event can be
    // slow, such as a ray against 10^5 triangles, and Ctrl+C must not wait for a thousand of them), the clock every
    // 64 calls.
    void at(double done) {
        progress_.done = done;
        if (stop_ && stop_->load(std::memory_order_relaxed)) throw WorkStopped();
        if (++calls_ % 64 == 0) look();
    }
    void look();    // tells if it is time, throws WorkStopped if asked to stop
    void finish();  // the stage is done: a last look, and a last word to a teller that was told anything
    [[nodiscard]] bool told_anything() const { return told_; }
    [[nodiscard]] const WorkProgress& progress() const { return progress_; }
    [[nodiscard]] double seconds() const;  // since the stage started

private:
    using Clock = std::chrono::steady_clock;
    Teller tell_;
    const std::atomic<bool>* stop_;
    double first_tell_after_, tell_every_;
    WorkProgress progress_;
    Clock::time_point stage_start_ = Clock::now(), work_start_ = Clock::now(), last_told_{};
    std::optional<std::pair<Clock::time_point, double>> rate_from_;  // the first look with something done, and how much
    std::uint64_t calls_ = 0;
    bool told_ = false;
};

// Drains a machine like run_to_end(), telling `meter` after each event how much is done: `count(event, done)`
// updates `done` (and may grow the meter's total). Without a meter it is run_to_end().
template <class Event, class Result, class Count>
Result drain(Steps<Event, Result>&& machine, WorkMeter* meter, Count count) {
    if (!meter) return std::move(machine).run_to_end();
    double done = 0;
    while (const Event* e = machine.next()) {
        count(*e, done);
        meter->at(done);
    }
    meter->finish();
    return std::move(machine).result();
}

}  // namespace hsr::algo
