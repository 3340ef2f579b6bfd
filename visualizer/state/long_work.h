// SPDX-License-Identifier: MIT
// Long work in the window: a lesson opening on a huge scene, End on a long run, an edit that reruns a big machine.
// Whoever starts it (the window) puts a WorkMeter in place for as long as the work lasts; the player ticks it for
// each event it pulls from a machine or folds into a view, so the window can show that it is busy (a progress frame)
// and Esc can stop the work: the meter throws WorkStopped between two events, which leaves the player consistent.
// One meter per thread: a measurement running off the main thread ticks nobody's.
#pragma once

#include "core/steps.h"
#include "core/work_meter.h"

namespace hsr::viz {

class LongWork {
public:
    // In place until destroyed; an inner one hides an outer one until it goes.
    explicit LongWork(algo::WorkMeter& meter);
    ~LongWork();
    LongWork(const LongWork&) = delete;
    LongWork& operator=(const LongWork&) = delete;

    // One step of work done (an event pulled or folded): counted, and the meter may tell or throw WorkStopped.
    static void tick();
    // A machine's run_to_end(), one tick per event: a session's own work (a tree for its figures, a reference
    // image) is shown and stoppable as its player's is.
    template <class Event, class Result>
    static Result run_to_end(algo::Steps<Event, Result>&& machine) {
        while (machine.next()) tick();
        return std::move(machine).result();
    }

private:
    algo::WorkMeter* outer_;
};

}  // namespace hsr::viz
