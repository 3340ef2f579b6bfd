// SPDX-License-Identifier: MIT
// R's measurement off the window's thread: the family's rows of `hsrviz report` are measured on a thread of their
// own while the window keeps drawing a progress bar, and a Cancel stops them before their next timed run. The
// window asks each frame whether the rows are in (take); leaving a lesson or closing the report cancels.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "analysis/measurement.h"

namespace hsr::viz {

class BackgroundMeasurement {
public:
    using Measure = std::function<std::vector<analysis::Measurement>(analysis::Progress&)>;

    BackgroundMeasurement() = default;
    BackgroundMeasurement(const BackgroundMeasurement&) = delete;
    BackgroundMeasurement& operator=(const BackgroundMeasurement&) = delete;
    ~BackgroundMeasurement();  // cancels and waits

    // Starts measure(progress) on its own thread (cancelling and waiting for one still running); or, where no thread
    // can be started (a browser page without workers), measures here and now, and take() has the rows at once.
    void start(Measure measure, bool on_a_thread = true);
    // Asks the running measurement to stop; it ends before its next timed run.
    void cancel();
    // Cancels and waits for the thread to end (a moment: the next timed run does not start); take() then has it.
    void stop();
    bool running() const;        // started and its answer not yet taken
    float fraction() const;      // of the planned runs done, 0 … 1

    // What a finished measurement gave, once: its rows, or why it has none (cancelled, or its error).
    struct Outcome {
        std::vector<analysis::Measurement> rows;
        std::string error;  // "" when it measured; "the measurement was cancelled" when cancelled
        bool cancelled = false;
    };
    std::optional<Outcome> take();

private:
    void wait();
    struct Shared;  // what the thread writes: the progress, the outcome and whether it is done
    std::shared_ptr<Shared> shared_;
    std::thread thread_;
};

}  // namespace hsr::viz
