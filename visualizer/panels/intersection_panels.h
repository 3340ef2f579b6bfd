// SPDX-License-Identifier: MIT
// The intersection test's state box: the volume in use, the ray under test, the call stack of IntersectionTest, the
// counts of volume and primitive tests and false alarms, and each ray's answer.
#pragma once

#include "panels/lesson_panels.h"
#include "state/intersection_session.h"

namespace hsr::viz {

void intersection_state_panel(const IntersectionSession& s, const PanelLayout& layout);
std::string volume_title(const algo::BoundingOptions& options);  // "14-DOP", "AABB", "progressive hulls (6, 14, 26)", …

}  // namespace hsr::viz
