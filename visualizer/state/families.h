// SPDX-License-Identifier: MIT
// The families as types: one closed variant of sessions, and the one place where a lesson's algorithm becomes a
// session type (with_family). Code that needs a family's own knowledge (its screen, its trace, its presets) visits
// the variant; code that does not (timeline, narration, pseudocode, questions) takes the common Session.
//
// What a session type provides is state/family_contract.h's FamilySessionType, checked on the list below: a new
// family is its own files, one line here (the include and the list), one in screens/screens.h, and its sources.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "state/family_contract.h"
#include "state/abuffer_session.h"
#include "state/backface_session.h"
#include "state/bsp_session.h"
#include "state/clip_session.h"
#include "state/composite_session.h"
#include "state/culling_session.h"
#include "state/depth_sort_session.h"
#include "state/forms_session.h"
#include "state/horizon_session.h"
#include "state/intersection_session.h"
#include "state/perspective_session.h"
#include "state/portal_session.h"
#include "state/raycast_session.h"
#include "state/roberts_session.h"
#include "state/scanline_session.h"
#include "state/zbuffer_session.h"
#include "state/zmerge_session.h"

namespace hsr::viz {

// A session type as a value, for with_family's callback: `[](auto family) { using S = typename decltype(family)::Session; }`.
template <class S>
struct Family {
    using Session = S;
};

// The session types, in one list: the variant below and the window's screens are made from it. Each must meet the
// family contract (a member missing is a compile error here that names it), and each machine of the registry must
// be played by one of them (checked below the list).
template <FamilySessionType S>
constexpr bool meets_the_family_contract() { return true; }  // called with a type that does not: the error names what is missing

template <class... S>
struct SessionTypes {
    static_assert((meets_the_family_contract<S>() && ...));
    using Variant = std::variant<std::unique_ptr<S>...>;
    template <template <class> class Of>
    using Tuple = std::tuple<Of<S>...>;
    template <class M>
    static constexpr bool some_plays = (PlaysMachineType<S, M> || ...);
};
using AllSessions = SessionTypes<ClipSession, BspSession, BackfaceSession, ZBufferSession, RayCastSession, ScanLineSession,
                                 ZMergeSession, DepthSortSession, PvsSession, PortalRenderSession, BoundsSession,
                                 HierarchyCullSession, OccluderSession, HizSession, HorizonSession,
                                 CompositeSession, RobertsSession, PerspectiveSession, ABufferSession, FormsSession,
                                 IntersectionSession>;

template <class Variant>
struct EveryMachinePlayed;
template <class... M>
struct EveryMachinePlayed<std::variant<M...>> : std::bool_constant<(AllSessions::some_plays<M> && ...)> {};
static_assert(EveryMachinePlayed<algo::Machine>::value,
              "a machine type of algo::Machine (registry.h) that no session type declares `static bool plays(M)` for");

namespace detail {
template <class F, class S, class... Rest>
decltype(auto) with_first_that_plays(const algo::AlgorithmInfo& algorithm, F& f, SessionTypes<S, Rest...>*) {
    if constexpr (sizeof...(Rest) == 0) {
        if (!session_plays<S>(algorithm.machine)) throw std::logic_error("no session type plays " + std::string(algorithm.id));
        return f(Family<S>{});
    } else {
        if (session_plays<S>(algorithm.machine)) return f(Family<S>{});
        return with_first_that_plays(algorithm, f, static_cast<SessionTypes<Rest...>*>(nullptr));
    }
}
}  // namespace detail

// Calls f(Family<S>{}) with the session type that plays `algorithm`: the one place an algorithm becomes a type.
template <class F>
decltype(auto) with_family(const algo::AlgorithmInfo& algorithm, F&& f) {
    return detail::with_first_that_plays(algorithm, f, static_cast<AllSessions*>(nullptr));
}

// A lesson being played, as its family's own type; `->` and `*` give the common Session.
class FamilySession {
public:
    using Variant = AllSessions::Variant;
    explicit FamilySession(Variant v) : v_(std::move(v)) {}
    Session* operator->() const { return &**this; }
    Session& operator*() const {
        return std::visit([](const auto& s) -> Session& { return *s; }, v_);
    }
    template <class F>
    decltype(auto) visit(F&& f) const {  // f(S&) with the session's own type
        return std::visit([&](const auto& s) -> decltype(auto) { return f(*s); }, v_);
    }
    template <class S>
    S* get_if() const {
        const auto* p = std::get_if<std::unique_ptr<S>>(&v_);
        return p ? p->get() : nullptr;
    }

private:
    Variant v_;
};

// The session for a lesson. Throws what loading the machine throws (InvalidInput).
FamilySession make_session(Lesson lesson, PlayerOptions options = {});

}  // namespace hsr::viz
