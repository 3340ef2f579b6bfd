// SPDX-License-Identifier: MIT
#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include "catch.h"
#include "core/work_meter.h"

using hsr::algo::Steps;
using hsr::algo::WorkMeter;
using hsr::algo::WorkProgress;

namespace {

Steps<int, int> counting_to(int n, std::atomic<bool>* stop_at_half = nullptr) {
    for (int i = 0; i < n; ++i) {
        if (stop_at_half && i == n / 2) stop_at_half->store(true);
        co_yield i;
    }
    co_return n;
}

}  // namespace

TEST_CASE("drain tells how far the work has come and gives the machine's answer") {
    std::vector<WorkProgress> told;
    WorkMeter meter([&](const WorkProgress& p) { told.push_back(p); }, nullptr, 0.0);
    meter.stage("counting", "numbers", 200'000);
    const int answer = hsr::algo::drain(counting_to(200'000), &meter, [](int, double& done) { ++done; });
    CHECK(answer == 200'000);
    REQUIRE(told.size() >= 2);  // at the stage's start, and its last word
    CHECK(told.front().done == 0);
    CHECK(told.back().finished);
    CHECK(told.back().done == 200'000);
    for (std::size_t k = 1; k < told.size(); ++k) CHECK(told[k].done >= told[k - 1].done);
}

TEST_CASE("a meter's teller waits before its first word, and then speaks at most twice a second") {
    std::vector<WorkProgress> told;
    WorkMeter quiet([&](const WorkProgress& p) { told.push_back(p); }, nullptr, 60.0);
    quiet.stage("short work", "steps", 10);
    (void)hsr::algo::drain(counting_to(100'000), &quiet, [](int, double& done) { ++done; });
    CHECK(told.empty());  // short work says nothing (and no last word either)

    WorkMeter chatty([&](const WorkProgress& p) { told.push_back(p); }, nullptr, 0.0);
    chatty.stage("work", "steps", 10);
    for (int k = 0; k < 100'000; ++k) chatty.at(k);
    CHECK(told.size() == 1);  // within half a second of the first word: no second
}

TEST_CASE("asked to stop, a drained machine ends with WorkStopped before its answer") {
    std::atomic<bool> stop{false};
    WorkMeter meter({}, &stop);
    meter.stage("counting", "numbers", 1e6);
    int seen = 0;
    CHECK_THROWS_AS(hsr::algo::drain(counting_to(1'000'000, &stop), &meter, [&](int, double& done) { done = ++seen; }),
                    hsr::algo::WorkStopped);
    CHECK(seen >= 500'000);
    CHECK(seen == 500'000 + 1);  // seen at the next event: the flag is looked at after every one
}

TEST_CASE("the progress sentence gives done, total, share, time and the time left") {
    const WorkProgress p{.stage = "ray cast", .unit = "rays", .done = 120'000, .total = 262'144, .seconds = 3.14, .seconds_left = 75.0};
    CHECK(p.sentence() == "ray cast: 120,000 of 262,144 rays (45 %), 3.1 s, about 1 min 15 s left");
    const WorkProgress none{.stage = "BSP build", .unit = "polygons placed", .done = 0, .total = 7};
    CHECK(none.sentence() == "BSP build: 0 of 7 polygons placed (0 %), 0.0 s");
    // work whose size nobody knows ahead (a lesson opening: its machine's events) says what is done, not "of 0"
    const WorkProgress open{.stage = "opening city.toml", .unit = "machine steps", .done = 1'234'567, .total = 0, .seconds = 2.5};
    CHECK(open.sentence() == "opening city.toml: 1,234,567 machine steps, 2.5 s");
    const WorkProgress done{.stage = "ray cast", .unit = "rays", .done = 7, .total = 7, .seconds = 1.0, .seconds_left = 0.0, .finished = true};
    CHECK(done.sentence() == "ray cast: 7 of 7 rays (100 %), 1.0 s");  // the last word has nothing left
    const WorkProgress unnamed{.seconds = 2.6};  // told before any stage was named (issue 53, item 12)
    CHECK(unnamed.sentence() == "getting ready, 2.6 s");
}

TEST_CASE("the time left is estimated from the rate since the first unit was done, not from the stage's set-up") {
    // issue 53, item 12: a ray cast that built its grid for minutes before the first ray said 'about 7682 h left'
    std::vector<WorkProgress> told;
    WorkMeter meter([&](const WorkProgress& p) { told.push_back(p); }, nullptr, 0.0, 0.0);
    meter.stage("ray cast", "rays", 100);
    std::this_thread::sleep_for(std::chrono::milliseconds(400));  // the set-up, before any ray
    meter.at(1);
    meter.look();
    CHECK(!told.back().seconds_left);  // one look with something done: no rate yet
    meter.at(50);
    meter.look();
    REQUIRE(told.back().seconds_left);
    CHECK(*told.back().seconds_left < 0.2);  // 50 rays in next to no time: next to no time left (it said 0.4 s and more)
    CHECK(told.back().seconds >= 0.4);       // the stage's own time still counts the set-up
}
