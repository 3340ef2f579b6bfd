// SPDX-License-Identifier: MIT
#include "state/background_measurement.h"

#include <atomic>
#include <mutex>

namespace hsr::viz {

struct BackgroundMeasurement::Shared {
    analysis::Progress progress;
    std::mutex mutex;
    std::optional<Outcome> outcome;  // set once, by the thread, when it ends
    bool taken = false;
};

BackgroundMeasurement::~BackgroundMeasurement() { stop(); }

void BackgroundMeasurement::stop() {
    cancel();
    wait();
}

void BackgroundMeasurement::start(Measure measure, bool on_a_thread) {
    stop();
    shared_ = std::make_shared<Shared>();
    const auto measure_into = [](Shared& shared, const Measure& m) {
        Outcome outcome;
        try {
            outcome.rows = m(shared.progress);
        } catch (const analysis::MeasurementCancelled& e) {
            outcome.error = e.what(), outcome.cancelled = true;
        } catch (const std::exception& e) {  // a scene file gone, say: said in the window, not a crash
            outcome.error = e.what();
        }
        const std::lock_guard lock(shared.mutex);
        shared.outcome = std::move(outcome);
    };
    if (!on_a_thread) return measure_into(*shared_, measure);
    thread_ = std::thread([measure_into, shared = shared_, measure = std::move(measure)] { measure_into(*shared, measure); });
}

void BackgroundMeasurement::cancel() {
    if (shared_) shared_->progress.cancel = true;
}

bool BackgroundMeasurement::running() const { return shared_ && !shared_->taken; }

float BackgroundMeasurement::fraction() const { return shared_ ? shared_->progress.fraction() : 0.f; }

std::optional<BackgroundMeasurement::Outcome> BackgroundMeasurement::take() {
    if (!shared_ || shared_->taken) return std::nullopt;
    {
        const std::lock_guard lock(shared_->mutex);
        if (!shared_->outcome) return std::nullopt;
    }
    wait();
    shared_->taken = true;
    return std::move(shared_->outcome);
}

void BackgroundMeasurement::wait() {
    if (thread_.joinable()) thread_.join();
}

}  // namespace hsr::viz
