// SPDX-License-Identifier: MIT
// Checks a scene's [expect] tables against the machines: every clipping machine that clips a primitive, the three
// back-face tests, BSP builds and traversals, the PVS, hidden-surface images against the ray cast, and machines
// that must refuse the scene. One outcome per expectation (per machine where several answer it), with the error
// measured where there is one. The scene tests and the report's catalogue of extreme cases both use it.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace hsr::analysis {

struct ExpectOutcome {
    std::string what;    // "expect.clip id 2 by liang_barsky", "expect.image zbuffer int16", …
    int line = 0;        // where the expectation is written
    bool passed = false;
    double error = 0;    // the measured error: relative vertex error, share of pixels differing, …
    std::string detail;  // what was found, in words (for test messages and the report)
};

std::vector<ExpectOutcome> check_expectations(const algo::Scene& scene);

}  // namespace hsr::analysis
