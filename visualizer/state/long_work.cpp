// SPDX-License-Identifier: MIT
#include "state/long_work.h"

namespace hsr::viz {
namespace {

thread_local algo::WorkMeter* meter_in_place = nullptr;

}  // namespace

LongWork::LongWork(algo::WorkMeter& meter) : outer_(meter_in_place) { meter_in_place = &meter; }

LongWork::~LongWork() { meter_in_place = outer_; }

void LongWork::tick() {
    if (!meter_in_place) return;
    meter_in_place->at(meter_in_place->progress().done + 1);  // the count is the meter's own
}

}  // namespace hsr::viz
