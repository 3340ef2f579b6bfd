// SPDX-License-Identifier: MIT
// Every family's screen, one per session type of state/families.h, and the one dispatch the window makes to them.
#pragma once

#include <concepts>
#include <optional>
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

// What a family's screen must provide (screens/screen.h's ScreenDefaults gives all but the first three): frame the
// 3D view when a lesson loads, fill the view and the caption, draw its canvases and state panel; take the mouse's
// gestures and carry out their edits; slide between steps; say whether the arrows step, drive or walk.
template <class S>
concept FamilyScreen = requires(Screen<S>& screen, const S& session, S& edited, OrbitCamera& camera, SceneFrame& scene,
                                PanelFrame& panels, const Pointer& pointer, const ViewGeometry& view, UiActions& actions,
                                glm::dvec2 point, bool flag, double seconds) {
    screen.frame(session, camera);
    screen.draw_scene(session, scene);
    screen.draw_panels(session, panels);
    { screen.pointer(session, pointer, view, actions) } -> std::same_as<bool>;
    { screen.apply(edited, actions) } -> std::same_as<bool>;
    { screen.edited_scene(session) } -> std::same_as<std::optional<algo::Scene>>;
    screen.before_step(session);
    screen.after_step(session, flag, seconds);
    { screen.gesture_point(session, point, view) } -> std::same_as<glm::vec2>;
    { screen.drives(session, flag) } -> std::same_as<bool>;
    { screen.walking(session) } -> std::same_as<bool>;
    { screen.two_d(session) } -> std::same_as<bool>;
};

// Every session type's screen meets the contract: else the call below names the session and the missing member.
template <FamilyScreen... S>
constexpr bool every_screen_meets_the_contract(SessionTypes<S...>*) { return true; }
static_assert(every_screen_meets_the_contract(static_cast<AllSessions*>(nullptr)));

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
