// SPDX-License-Identifier: MIT
// Every family's screen, one per session type of state/families.h, and the one dispatch the window makes to them.
#pragma once

#include <tuple>
#include <type_traits>

#include "screens/abuffer_screen.h"
#include "screens/backface_screen.h"
#include "screens/bsp_screen.h"
#include "screens/clip_screen.h"
#include "screens/composite_screen.h"
#include "screens/culling_screen.h"
#include "screens/depth_sort_screen.h"
#include "screens/forms_screen.h"
#include "screens/horizon_screen.h"
#include "screens/intersection_screen.h"
#include "screens/perspective_screen.h"
#include "screens/portal_screen.h"
#include "screens/raycast_screen.h"
#include "screens/roberts_screen.h"
#include "screens/scanline_screen.h"
#include "screens/zbuffer_screen.h"
#include "screens/zmerge_screen.h"
#include "state/families.h"

namespace hsr::viz {

// One screen per session type, for the window's whole life (its gestures and tween carry over between frames).
using Screens = AllSessions::Tuple<Screen>;

// Calls f(session, screen) with the family's own session type and its screen.
template <class F>
decltype(auto) with_screen(const FamilySession& session, Screens& screens, F&& f) {
    return session.visit([&](auto& s) -> decltype(auto) {
        return f(s, std::get<Screen<std::decay_t<decltype(s)>>>(screens));
    });
}

}  // namespace hsr::viz
