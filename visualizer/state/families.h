// SPDX-License-Identifier: MIT
// The families as types: one closed variant of sessions, and the one place where a lesson's algorithm becomes a
// session type (with_family). Code that needs a family's own knowledge (its screen, its trace, its presets) visits
// the variant; code that does not (timeline, narration, pseudocode, questions) takes the common Session.
//
// Each session type S provides, beside the Session interface:
//   S(Lesson, PlayerOptions)                           plays the lesson
//   static S::RunType machine(const Lesson&)           the lesson's machine and first view (wired once, here)
//   static std::string sentence_of(const Event&, const View&)    the sentence of an event, the view after it
//   static FamilyFacts facts                          what the presets and the report need (below)
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/overloaded.h"
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

// The session types, in one list: the variant below and the window's screens are made from it.
template <class... S>
struct SessionTypes {
    using Variant = std::variant<std::unique_ptr<S>...>;
    template <template <class> class Of>
    using Tuple = std::tuple<Of<S>...>;
};
using AllSessions = SessionTypes<ClipSession, BspSession, BackfaceSession, ZBufferSession, RayCastSession, ScanLineSession,
                                 ZMergeSession, DepthSortSession, PvsSession, PortalRenderSession, BoundsSession,
                                 HierarchyCullSession, OccluderSession, HizSession, HorizonSession,
                                 CompositeSession, RobertsSession, PerspectiveSession, ABufferSession, FormsSession,
                                 IntersectionSession>;

// Calls f(Family<S>{}) with the session type that plays `algorithm`: the one place an algorithm becomes a type.
template <class F>
decltype(auto) with_family(const algo::AlgorithmInfo& algorithm, F&& f) {
    using namespace algo;
    return std::visit(overloaded{
                          [&](ClipAlgorithm) { return f(Family<ClipSession>{}); },
                          [&](BspMachine) { return f(Family<BspSession>{}); },
                          [&](BackfaceTest) { return f(Family<BackfaceSession>{}); },
                          [&](ZBufferMachine) { return f(Family<ZBufferSession>{}); },
                          [&](Acceleration) { return f(Family<RayCastSession>{}); },
                          [&](ScanLineMachine) { return f(Family<ScanLineSession>{}); },
                          [&](ZMergeMachine) { return f(Family<ZMergeSession>{}); },
                          [&](HorizonMachine) { return f(Family<HorizonSession>{}); },
                          [&](CompositeMachine) { return f(Family<CompositeSession>{}); },
                          [&](RobertsMachine) { return f(Family<RobertsSession>{}); },
                          [&](PerspectiveMachine) { return f(Family<PerspectiveSession>{}); },
                          [&](ABufferMachine) { return f(Family<ABufferSession>{}); },
                          [&](FormsMachine) { return f(Family<FormsSession>{}); },
                          [&](IntersectionMachine) { return f(Family<IntersectionSession>{}); },
                          [&](DepthSortMachine) { return f(Family<DepthSortSession>{}); },
                          [&](PortalMachine m) {
                              return m == PortalMachine::pvs ? f(Family<PvsSession>{}) : f(Family<PortalRenderSession>{});
                          },
                          [&](CullingMachine m) {
                              switch (m) {
                                  case CullingMachine::bounds: return f(Family<BoundsSession>{});
                                  case CullingMachine::frustum:
                                  case CullingMachine::detail: return f(Family<HierarchyCullSession>{});
                                  case CullingMachine::occluders: return f(Family<OccluderSession>{});
                                  case CullingMachine::hiz: break;
                              }
                              return f(Family<HizSession>{});
                          },
                      },
                      algorithm.machine);
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
