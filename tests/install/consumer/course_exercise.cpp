// SPDX-License-Identifier: MIT
// A teacher's own exercise written against the installed machines: Cohen–Sutherland clips a segment that leaves the
// view volume through x = w; the exercise prints the machine's sentences, counts its outcodes and checks the answer.
#include <cmath>
#include <cstdio>
#include <variant>

#include "clipping/clip_events.h"
#include "clipping/cohen_sutherland.h"

int main() {
    using namespace hsr::algo;
    auto machine = cohen_sutherland(ClipSegment{1, {0, 0, 0, 1}, {3, 0.5, 0, 1}});
    int outcodes = 0;
    while (const ClipEvent* event = machine.next()) {
        if (std::holds_alternative<OutcodeComputed>(*event)) ++outcodes;
        std::printf("%s\n", describe(*event, ClipSpace::homogeneous).c_str());
    }
    const SegmentClip& answer = machine.result();
    // the visible part runs from the first point to where x = w: x = 1, y = 0.5 / 3
    const bool right = answer.outcome == ClipOutcome::clipped && std::abs(answer.b.x - 1.0) < 1e-12 && outcodes >= 2;
    std::printf("outcodes computed: %d; visible part ends at x = %g, y = %g: %s\n", outcodes, double(answer.b.x),
                double(answer.b.y), right ? "right" : "WRONG");
    return right ? 0 : 1;
}
