// SPDX-License-Identifier: MIT
// Ctrl+C during a command's long work asks the work to stop at its next look (no output is left); a second Ctrl+C
// ends the program at once, as it would have without us. One at a time: the guard puts back what it found.
#pragma once

#include <atomic>

namespace hsr::viz {

class StopOnInterrupt {
public:
    StopOnInterrupt();
    ~StopOnInterrupt();
    StopOnInterrupt(const StopOnInterrupt&) = delete;
    StopOnInterrupt& operator=(const StopOnInterrupt&) = delete;
    const std::atomic<bool>& asked;  // set by the first Ctrl+C

private:
    void (*before_)(int);
};

}  // namespace hsr::viz
