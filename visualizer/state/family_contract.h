// SPDX-License-Identifier: MIT
// What a family's session type must provide, as code: state/families.h's list of session types accepts only types
// that meet FamilySessionType, so a session missing a member does not compile, and the compiler names the member.
//
// A session type S plays one or more of the registry's machines: for each machine type M of algo::Machine it plays,
// it declares `static bool plays(M)` (true for the values it plays: the portal family's PVS and rendering are two
// sessions over one PortalMachine). with_family picks, for a lesson's algorithm, the one session that plays it.
#pragma once

#include <concepts>
#include <string>
#include <type_traits>
#include <variant>

#include "registry.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

// S plays some values of machine type M.
template <class S, class M>
concept PlaysMachineType = requires(M m) {
    { S::plays(m) } -> std::same_as<bool>;
};

template <class S, class Variant>
struct PlaysSomeMachine;
template <class S, class... M>
struct PlaysSomeMachine<S, std::variant<M...>> : std::bool_constant<(PlaysMachineType<S, M> || ...)> {};

// A family's session: the player of a lesson (Session), made from a lesson, its machine wired in one place, its
// events put in words as the view after them names things, its facts for the presets and the report, and the
// machines it plays.
template <class S>
concept FamilySessionType =
    std::derived_from<S, Session> && std::constructible_from<S, Lesson, PlayerOptions> &&
    requires(const Lesson& lesson, const typename S::EventType& event, const typename S::ViewType& view) {
        { S::machine(lesson) } -> std::same_as<typename S::RunType>;           // the lesson's machine and first view
        { S::sentence_of(event, view) } -> std::convertible_to<std::string>;  // describe(event), in the view's names
        { S::facts } -> std::convertible_to<const FamilyFacts&>;              // topic, extreme cases, random scene, report
    } &&
    PlaysSomeMachine<S, algo::Machine>::value;  // a `static bool plays(M)` for a machine type M of the registry

// Whether session type S plays `machine` (false where S plays none of the machine's type).
template <class S>
bool session_plays(const algo::Machine& machine) {
    return std::visit(
        [](auto m) {
            if constexpr (PlaysMachineType<S, decltype(m)>) return S::plays(m);
            else return false;
        },
        machine);
}

}  // namespace hsr::viz
