// SPDX-License-Identifier: MIT
// The player: seek(k) equals folding events [0, k) from the start, for every k, on real traces.
#include <atomic>
#include <random>

#include "catch.h"
#include "clipping/clip_test_helpers.h"
#include "event_strings.h"
#include "state/clip_view.h"
#include "state/event_log.h"
#include "state/lesson.h"
#include "state/long_work.h"
#include "state/player.h"

using namespace hsr::algo;
using namespace hsr::viz;

namespace {

using TestPlayer = Player<ClipEvent, std::vector<PrimitiveClip>, ClipView>;

bool same_view(const ClipView& a, const ClipView& b) {
    if (a.primitives.size() != b.primitives.size()) return false;
    for (std::size_t i = 0; i < a.primitives.size(); ++i) {
        const auto &x = a.primitives[i], &y = b.primitives[i];
        if (x.id != y.id || x.status != y.status || x.outcome != y.outcome || x.visible != y.visible) return false;
    }
    return a.active == b.active && a.p1 == b.p1 && a.p2 == b.p2 && a.c1 == b.c1 && a.c2 == b.c2 && a.c1_known == b.c1_known && a.c2_known == b.c2_known &&
           a.round == b.round && a.plane == b.plane && a.intersections == b.intersections &&
           a.t_enter == b.t_enter && a.t_leave == b.t_leave && a.stage_input == b.stage_input &&
           a.stage_output == b.stage_output && a.edge == b.edge && a.bound_reached == b.bound_reached;
}

ClipJob job_for(ClipSpace s, int n) {
    std::mt19937_64 rng(21);
    ClipJob job{.space = s};
    for (int i = 0; i < n; ++i)
        job.segments.push_back({i + 1, hsr::test::random_point(rng, s), hsr::test::random_point(rng, s)});
    for (int i = 0; i < n; ++i) {
        ClipPolygon p{n + i + 1, {}};
        for (int k = 0; k < 5; ++k) p.vertices.push_back(hsr::test::random_point(rng, s));
        job.polygons.push_back(p);
    }
    return job;
}

}  // namespace

TEST_CASE("the event log returns each event as it was pushed", "[state][log]") {
    EventLog<ClipEvent> log;
    const std::vector<ClipEvent> events = {SegmentStarted{1, {1, 2, 3, 4}, {5, 6, 7, 8}}, CodesCompared{{3}, {4}},
                                           StageStarted{ClipPlane::x_min, 9}, CodesCompared{{5}, {6}},
                                           EdgeClassified{ClipPlane::y_max, EdgeCase::out_in, true, 7, 0.5, -0.25, {1, 2, 3, 4}}};
    for (const auto& e : events) log.push(e);
    REQUIRE(log.size() == events.size());
    for (std::size_t k = 0; k < events.size(); ++k) CHECK(log.at(k) == events[k]);
}

TEST_CASE("a failing comparison of events prints each as its trace line, not as bytes", "[state][log]") {
    const ClipEvent e = EdgeClassified{ClipPlane::y_max, EdgeCase::out_in, true, 7, 0.5, -0.25, {1, 2, 3, 4}};
    const std::string printed = Catch::Detail::stringify(e);
    CHECK_THAT(printed, Catch::Contains("\"kind\":\"EdgeClassified\""));
    CHECK_THAT(printed, Catch::Contains("\"plane\":\"y max\""));  // the fields by name, in words
}

TEST_CASE("seek(k) equals a fold of the first k events for every k", "[state][player]") {
    const ClipSpace space = GENERATE(ClipSpace::cube, ClipSpace::homogeneous);
    const ClipAlgorithm algorithm = GENERATE(ClipAlgorithm::cohen_sutherland, ClipAlgorithm::sutherland_hodgman);
    const ClipJob job = job_for(space, 40);
    // Reference: every prefix fold, from a second run of the same machine.
    std::vector<ClipView> folds{initial_view(job, algorithm)};
    for (const auto& e : clip_scene(job, algorithm)) {
        folds.push_back(folds.back());
        reduce(folds.back(), e);
    }
    const std::size_t n = folds.size() - 1;
    REQUIRE(n > 300);

    TestPlayer player(clip_scene(job, algorithm), initial_view(job, algorithm), {.min_keyframe_interval = 16, .keyframe_bytes_per_event = 1u << 20});  // many keyframes
    SECTION("seeking forward to every k in order") {
        for (std::size_t k = 0; k <= n; ++k) {
            player.seek(k);
            REQUIRE(player.cursor() == k);
            REQUIRE(same_view(player.view(), folds[k]));
        }
        CHECK(player.keyframe_count() > 1);
    }
    SECTION("seeking to every k in a shuffled order") {
        player.seek_end();
        REQUIRE(player.cursor() == n);
        std::vector<std::size_t> ks(n + 1);
        for (std::size_t k = 0; k <= n; ++k) ks[k] = k;
        std::shuffle(ks.begin(), ks.end(), std::mt19937_64(3));
        for (std::size_t k : ks) {
            player.seek(k);
            REQUIRE(same_view(player.view(), folds[k]));
        }
    }
    SECTION("stepping back then forward returns to the same view") {
        player.seek(n / 2);
        for (int i = 0; i < 50; ++i) player.step_back();
        CHECK(same_view(player.view(), folds[n / 2 - 50]));
        for (int i = 0; i < 50; ++i) player.step_forward();
        CHECK(same_view(player.view(), folds[n / 2]));
    }
    SECTION("seeking past the end stops at the end, and the result is there") {
        player.seek(n + 100);
        CHECK(player.cursor() == n);
        CHECK(player.at_end());
        REQUIRE(player.result() != nullptr);
        CHECK(answers(player.view()) == *player.result());
    }
}

TEST_CASE("the player pulls events lazily", "[state][player]") {
    const ClipJob job = job_for(ClipSpace::cube, 10);
    TestPlayer player(clip_scene(job, ClipAlgorithm::cohen_sutherland),
                      initial_view(job, ClipAlgorithm::cohen_sutherland));
    CHECK(player.known() == 0);
    player.step_forward();
    CHECK(player.known() == 1);
    player.seek(5);
    CHECK(player.known() == 5);
    CHECK_FALSE(player.complete());
}

TEST_CASE("a player with an event cap ends there instead of pulling forever", "[state][player]") {
    const ClipJob job = job_for(ClipSpace::cube, 10);
    TestPlayer player(clip_scene(job, ClipAlgorithm::cohen_sutherland),
                      initial_view(job, ClipAlgorithm::cohen_sutherland), {.max_events = 7});
    player.seek_end();
    CHECK(player.cursor() == 7);
    CHECK(player.capped());
    CHECK(player.at_end());
}

TEST_CASE("a player whose log reaches its byte cap ends there, at a multiple of 4,096 events", "[state][player]") {
    const ClipJob job = job_for(ClipSpace::cube, 1500);
    TestPlayer player(clip_scene(job, ClipAlgorithm::cohen_sutherland),
                      initial_view(job, ClipAlgorithm::cohen_sutherland), {.max_log_bytes = 1});
    player.seek_end();
    CHECK(player.cursor() == 4096);
    CHECK(player.capped());
    CHECK(player.at_end());
    CHECK_FALSE(player.complete());
    TestPlayer roomy(clip_scene(job, ClipAlgorithm::cohen_sutherland), initial_view(job, ClipAlgorithm::cohen_sutherland));
    roomy.seek_end();
    CHECK(roomy.cursor() > 4096);  // the same run is longer
    CHECK(roomy.complete());
}

TEST_CASE("seek(k) equals a fold of the first k events on every shipped lesson's trace", "[state][player][lesson]") {
    for (const char* file : {"01_cohen_sutherland.toml", "02_liang_barsky.toml", "03_sutherland_hodgman.toml"}) {
        INFO(file);
        const Lesson lesson = load_lesson(data_dir() + "/lessons/" + file);
        const auto algorithm = machine_of<ClipAlgorithm>(lesson);
        const ClipJob job = clip_job(lesson.scene);
        std::vector<ClipView> folds{initial_view(job, algorithm)};
        for (const auto& e : clip_scene(job, algorithm)) {
            folds.push_back(folds.back());
            reduce(folds.back(), e);
        }
        TestPlayer player(clip_scene(job, algorithm), initial_view(job, algorithm), {.min_keyframe_interval = 4});
        player.seek_end();
        for (std::size_t k = folds.size(); k-- > 0;) {  // backwards: every seek goes through a keyframe
            player.seek(k);
            REQUIRE(same_view(player.view(), folds[k]));
        }
    }
}

TEST_CASE("long work in the window: the player ticks the meter in place, and a stop between two events leaves it consistent",
          "[state][player][long]") {
    const ClipJob job = job_for(ClipSpace::cube, 80);
    const auto algorithm = ClipAlgorithm::liang_barsky;
    std::vector<ClipView> folds{initial_view(job, algorithm)};
    for (const auto& e : clip_scene(job, algorithm)) {
        folds.push_back(folds.back());
        reduce(folds.back(), e);
    }
    const std::size_t n = folds.size() - 1;
    REQUIRE(n > 600);
    // told at every look (every 64 ticks); asks to stop once 200 steps are done: the look at 256 sees it, the tick
    // after it throws
    std::atomic<bool> stop{false};
    int told = 0;
    WorkMeter meter([&](const WorkProgress& p) { ++told, stop = stop || p.done >= 200; }, &stop, 0.0, 0.0);
    meter.stage("opening", "machine steps", 0);
    TestPlayer player(clip_scene(job, algorithm), initial_view(job, algorithm), {.min_keyframe_interval = 16});

    SECTION("pulling stops with the event that was being pulled in the log") {
        {
            LongWork in_place(meter);
            CHECK_THROWS_AS(player.seek_end(), WorkStopped);
        }
        CHECK(told > 1);
        CHECK(player.known() == 257);
        CHECK(player.cursor() == 0);
        player.seek_end();  // no meter in place any more: nothing ticks, nothing stops
        CHECK(player.cursor() == n);
        CHECK(same_view(player.view(), folds[n]));
    }
    SECTION("folding stops at a step whose view is the fold of the events before it") {
        player.prefetch(n + 1);
        REQUIRE(player.complete());
        {
            LongWork in_place(meter);
            CHECK_THROWS_AS(player.seek(n), WorkStopped);
        }
        CHECK(player.cursor() == 257);
        CHECK(same_view(player.view(), folds[257]));
        player.seek(n);
        CHECK(same_view(player.view(), folds[n]));
    }
    SECTION("an inner meter hides the outer one until it goes; a machine run to its end ticks once per event") {
        std::atomic<bool> never{false};
        WorkMeter inner({}, &never);
        inner.stage("inner", "machine steps", 0);
        LongWork outer_place(meter);
        {
            LongWork inner_place(inner);
            const auto clipped = LongWork::run_to_end(clip_scene(job, algorithm));
            CHECK(clipped == answers(folds[n]));  // the same answers as the player's fold
            CHECK(inner.progress().done == double(n));
        }
        CHECK(told == 1);  // the outer meter was told only at its stage's start
        LongWork::tick();
        CHECK(meter.progress().done == 1);  // its count goes on from where it was
    }
}
