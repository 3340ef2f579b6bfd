// SPDX-License-Identifier: MIT
#include "state/interrupt.h"

#include <csignal>

namespace hsr::viz {
namespace {

std::atomic<bool> interrupt_asked{false};

extern "C" void on_interrupt(int) {
    interrupt_asked.store(true);
    std::signal(SIGINT, SIG_DFL);
}

}  // namespace

StopOnInterrupt::StopOnInterrupt() : asked(interrupt_asked), before_(std::signal(SIGINT, on_interrupt)) { interrupt_asked.store(false); }

StopOnInterrupt::~StopOnInterrupt() { std::signal(SIGINT, before_); }

}  // namespace hsr::viz
