// SPDX-License-Identifier: MIT
#include "core/work_meter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hsr::algo {

std::string whole_number(double x) {
    const std::string digits = std::to_string(static_cast<long long>(std::llround(std::clamp(x, 0.0, 9e18))));
    std::string grouped;  // built anew, not by insert(): g++ 12 at -O3 warns of a false overlap in that (-Wrestrict)
    for (std::size_t k = 0; k < digits.size(); ++k) {
        if (k > 0 && (digits.size() - k) % 3 == 0) grouped += ',';
        grouped += digits[k];
    }
    return grouped;
}

namespace {

std::string duration(double s) {
    char b[32];
    if (s < 60) std::snprintf(b, sizeof b, "%.1f s", s);
    else if (s < 3600) std::snprintf(b, sizeof b, "%d min %02d s", int(s) / 60, int(s) % 60);
    else std::snprintf(b, sizeof b, "%d h %02d min", int(s) / 3600, int(s) % 3600 / 60);
    return b;
}

}  // namespace

std::string WorkProgress::sentence() const {
    // before any stage is named (the solid occluders' set-up said "hsrviz: : 0 , 2.6 s"): "getting ready, 2.6 s"
    if (stage.empty() && unit.empty() && total <= 0) return "getting ready, " + duration(seconds);
    std::string s = (stage.empty() ? "working" : stage) + ": " + whole_number(done) + (total > 0 ? " of " + whole_number(total) : std::string()) +
                    (unit.empty() ? "" : " " + unit);
    if (total > 0) s += " (" + std::to_string(int(std::clamp(100 * done / total, 0.0, 100.0))) + " %)";
    s += ", " + duration(seconds);
    if (seconds_left && !finished) s += ", about " + duration(*seconds_left) + " left";
    return s;
}

WorkMeter::WorkMeter(Teller tell, const std::atomic<bool>* stop, double first_tell_after_seconds, double tell_every_seconds)
    : tell_(std::move(tell)), stop_(stop), first_tell_after_(first_tell_after_seconds), tell_every_(tell_every_seconds) {}

void WorkMeter::stage(std::string name, std::string unit, double total) {
    progress_ = {.stage = std::move(name), .unit = std::move(unit), .total = total};
    stage_start_ = Clock::now();
    rate_from_.reset();
    look();
}

void WorkMeter::look() {
    if (stop_ && stop_->load(std::memory_order_relaxed)) throw WorkStopped();
    if (!tell_) return;
    const auto now = Clock::now();
    const auto seconds = [](Clock::duration d) { return std::chrono::duration<double>(d).count(); };
    // The rate is measured from the first look that finds something done: the stage's set-up before its first unit
    // (a grid built before the first ray) is not a unit's time ("about 7682 h left" for a 144 s run)
    if (!rate_from_ && progress_.done > 0) rate_from_ = std::pair(now, progress_.done);
    if (seconds(now - work_start_) < first_tell_after_ || (told_ && seconds(now - last_told_) < tell_every_)) return;
    progress_.seconds = seconds(now - stage_start_);
    progress_.seconds_left.reset();
    if (rate_from_ && progress_.done > rate_from_->second && progress_.total >= progress_.done)
        progress_.seconds_left = seconds(now - rate_from_->first) * (progress_.total - progress_.done) / (progress_.done - rate_from_->second);
    tell_(progress_);
    told_ = true;
    last_told_ = now;
}

double WorkMeter::seconds() const { return std::chrono::duration<double>(Clock::now() - stage_start_).count(); }

void WorkMeter::finish() {
    look();
    if (!tell_ || !told_) return;
    progress_.finished = true;
    progress_.seconds = std::chrono::duration<double>(Clock::now() - stage_start_).count();
    progress_.seconds_left = 0;
    tell_(progress_);
    progress_.finished = false;
}

}  // namespace hsr::algo
