// SPDX-License-Identifier: MIT
// The family contract (state/family_contract.h) in force: a session type that misses a member is refused, every
// algorithm of the registry is played by exactly one session type, and one template test runs every session type
// over its lessons: seeking to a step shows what stepping there shows, every event lights a pseudocode line, and
// the trace is the same bytes twice.
#include <algorithm>
#include <filesystem>
#include <set>
#include <tuple>

#include "catch.h"
#include "state/families.h"
#include "state/trace.h"

using namespace hsr::viz;

namespace {

// A session type with one member of the contract hidden by a member of the same name that does not fit it.
struct HidesPlays : RobertsSession {
    using RobertsSession::RobertsSession;
    static void plays() {}
};
struct HidesFacts : RobertsSession {
    using RobertsSession::RobertsSession;
    static constexpr int facts = 0;
};
struct HidesSentence : RobertsSession {
    using RobertsSession::RobertsSession;
    static int sentence_of() { return 0; }
};
struct HidesMachine : RobertsSession {
    using RobertsSession::RobertsSession;
    static int machine(const Lesson&) { return 0; }
};

template <class T>
using Same = T;
using EverySession = AllSessions::Tuple<Same>;  // std::tuple<ClipSession, BspSession, …>: Catch's list of types

// The shipped lessons, loaded once.
const std::vector<Lesson>& shipped_lessons() {
    static const std::vector<Lesson> lessons = [] {
        std::vector<std::filesystem::path> files;
        for (const auto& f : std::filesystem::directory_iterator(HSR_SOURCE_DIR "/lessons"))
            if (f.path().extension() == ".toml") files.push_back(f.path());
        std::sort(files.begin(), files.end());
        std::vector<Lesson> out;
        for (const auto& f : files) out.push_back(load_lesson(f.string()));
        return out;
    }();
    return lessons;
}

template <class S>
std::vector<const Lesson*> lessons_of() {
    std::vector<const Lesson*> mine;
    for (const Lesson& l : shipped_lessons())
        if (session_plays<S>(l.algorithm.machine)) mine.push_back(&l);
    return mine;
}

}  // namespace

TEST_CASE("a session type missing a member of the family contract is refused", "[state][families]") {
    STATIC_REQUIRE(FamilySessionType<RobertsSession>);
    STATIC_REQUIRE_FALSE(FamilySessionType<HidesPlays>);
    STATIC_REQUIRE_FALSE(FamilySessionType<HidesFacts>);
    STATIC_REQUIRE_FALSE(FamilySessionType<HidesSentence>);
    STATIC_REQUIRE_FALSE(FamilySessionType<HidesMachine>);
}

TEST_CASE("every algorithm of the registry is played by exactly one session type, the one with_family picks", "[state][families]") {
    for (const hsr::algo::AlgorithmInfo& a : hsr::algo::algorithms()) {
        std::size_t count = 0;
        const auto count_players = [&]<class... S>(SessionTypes<S...>*) { count = (std::size_t(session_plays<S>(a.machine)) + ...); };
        count_players(static_cast<AllSessions*>(nullptr));
        INFO(a.id);
        CHECK(count == 1);
        const bool picked = with_family(a, [&](auto family) { return session_plays<typename decltype(family)::Session>(a.machine); });
        CHECK(picked);
    }
}

TEMPLATE_LIST_TEST_CASE("every session type plays its lessons by the contract: seek is stepping, every event lights a line, "
                        "the trace is stable", "[state][families]", EverySession) {
    using S = TestType;
    const std::vector<const Lesson*> lessons = lessons_of<S>();
    REQUIRE_FALSE(lessons.empty());  // every session type is taught by a shipped lesson
    for (const Lesson* lesson : lessons) {
        INFO(lesson->title);
        S stepped(*lesson, {}), sought(*lesson, {});
        stepped.seek_end();
        const std::size_t n = stepped.cursor();
        REQUIRE(n > 0);
        // every event lights a line of the lesson's pseudocode
        std::set<std::size_t> dark;
        for (std::size_t k = 1; k <= n; ++k) {
            stepped.seek(k);
            if (stepped.current_line() < 0) dark.insert(k - 1);
        }
        CHECK(dark.empty());
        // seeking to step k (from the end, from the start) arrives where micro-stepping from the start does
        stepped.seek(0);
        const std::size_t stride = std::max<std::size_t>(1, n / 24);
        for (std::size_t k = 0; k <= n; ++k) {
            if (k > 0) stepped.micro_step();
            if (k % stride != 0 && k != n) continue;
            sought.seek_end();
            sought.seek(k);
            REQUIRE(sought.cursor() == stepped.cursor());
            CHECK(played_trace(sought).hash == played_trace(stepped).hash);
            CHECK(sought.current_line() == stepped.current_line());
        }
        // the same lesson, the same bytes: the trace written twice, and the played trace of the whole run
        const TraceSummary once = trace_lesson(*lesson, nullptr), twice = trace_lesson(*lesson, nullptr);
        CHECK(once.hash == twice.hash);
        CHECK(once.events == n);
        CHECK(played_trace(stepped).hash == once.hash);
    }
}
