// SPDX-License-Identifier: MIT
// Catch prints a machine's event as its trace line (kind and every field, as JSON) when a comparison of events fails,
// instead of the bytes of a variant: for every event type a session of state/families.h plays.
#pragma once

#include <string>
#include <type_traits>

#include "catch.h"
#include "state/families.h"
#include "state/trace.h"

namespace hsr::test {

template <class E>
inline constexpr bool is_session_event = []<class... S>(viz::SessionTypes<S...>*) {
    return (std::is_same_v<E, typename S::EventType> || ...);
}(static_cast<viz::AllSessions*>(nullptr));

}  // namespace hsr::test

namespace Catch {
template <class E>
    requires hsr::test::is_session_event<E>
struct StringMaker<E> {
    static std::string convert(const E& e) { return hsr::viz::trace_line(0, e, ""); }
};
}  // namespace Catch
