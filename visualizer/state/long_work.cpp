// SPDX-License-Identifier: MIT
#include "state/long_work.h"

namespace hsr::viz {
namespace {

thread_local algo::WorkMeter* meter_in_place = nullptr;
thread_local double steps_done = 0;

}  // namespace

LongWork::LongWork(algo::WorkMeter& meter) : outer_(meter_in_place), outer_steps_(steps_done) {
    meter_in_place = &meter;
    steps_done = 0;
}

LongWork::~LongWork() {
    meter_in_place = outer_;
    steps_done = outer_steps_;
}

void LongWork::tick() {
    if (!meter_in_place) return;
    meter_in_place->at(++steps_done);
}

}  // namespace hsr::viz
