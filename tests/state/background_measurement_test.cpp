// SPDX-License-Identifier: MIT
// R's measurement on a thread of its own: rows come in once, a cancel ends it before its next timed run, an error is
// an outcome (not a crash), and the progress grows while it runs.
#include "catch.h"

#include <chrono>
#include <stdexcept>
#include <thread>

#include "state/background_measurement.h"

using hsr::analysis::Measurement;
using hsr::analysis::Progress;
using hsr::analysis::ReportOptions;
using hsr::viz::BackgroundMeasurement;

namespace {

// Waits (a few seconds at most) for the measurement's outcome.
std::optional<BackgroundMeasurement::Outcome> outcome_of(BackgroundMeasurement& m) {
    for (int k = 0; k < 2000; ++k) {
        if (auto o = m.take()) return o;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return std::nullopt;
}

// A family of `runs` timed runs of 1 ms each, told to the progress as the report's families tell it.
std::vector<Measurement> slow_family(Progress& p, int runs) {
    const ReportOptions o{.quick = true, .repeats = 1, .progress = &p};
    hsr::analysis::plan_runs(o, runs);
    std::vector<Measurement> rows;
    for (int k = 0; k < runs; ++k)
        rows.push_back({.median_ms = hsr::analysis::median_ms(o, [] { std::this_thread::sleep_for(std::chrono::milliseconds(1)); })});
    return rows;
}

}  // namespace

TEST_CASE("a measurement in the background gives its rows once", "[state][report]") {
    BackgroundMeasurement m;
    CHECK_FALSE(m.running());
    m.start([](Progress& p) { return slow_family(p, 5); });
    CHECK(m.running());
    const auto o = outcome_of(m);
    REQUIRE(o);
    CHECK(o->error.empty());
    CHECK(o->rows.size() == 5);
    CHECK_FALSE(m.running());
    CHECK_FALSE(m.take());  // taken once
    CHECK(m.fraction() == 1.f);
}

TEST_CASE("where no thread can be started, the measurement runs at once and take() has it", "[state][report]") {
    BackgroundMeasurement m;
    m.start([](Progress& p) { return slow_family(p, 3); }, false);
    const auto o = m.take();  // no waiting: it ran inside start
    REQUIRE(o);
    CHECK(o->error.empty());
    CHECK(o->rows.size() == 3);
    CHECK_FALSE(m.running());
    m.start([](Progress&) -> std::vector<Measurement> { throw std::runtime_error("a scene file is gone"); }, false);
    const auto failed = m.take();
    REQUIRE(failed);
    CHECK(failed->error == "a scene file is gone");
}

TEST_CASE("a cancelled measurement ends before its next run and says it was cancelled", "[state][report]") {
    BackgroundMeasurement m;
    m.start([](Progress& p) { return slow_family(p, 100000); });  // 100 s if nobody stopped it
    for (int k = 0; k < 2000 && m.fraction() == 0.f; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    const float part = m.fraction();
    CHECK(part > 0.f);
    CHECK(part < 0.5f);
    const auto start = std::chrono::steady_clock::now();
    m.cancel();
    const auto o = outcome_of(m);
    REQUIRE(o);
    CHECK(o->cancelled);
    CHECK(o->rows.empty());
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(4));
    CHECK_FALSE(m.running());
}

TEST_CASE("a measurement that fails is an outcome with its error, and a new one may start", "[state][report]") {
    BackgroundMeasurement m;
    m.start([](Progress&) -> std::vector<Measurement> { throw std::runtime_error("cells_lecture.toml: cannot open"); });
    const auto o = outcome_of(m);
    REQUIRE(o);
    CHECK_FALSE(o->cancelled);
    CHECK(o->error == "cells_lecture.toml: cannot open");
    m.start([](Progress& p) { return slow_family(p, 2); });
    const auto again = outcome_of(m);
    REQUIRE(again);
    CHECK(again->rows.size() == 2);
}

TEST_CASE("a measurement still running when its owner goes is cancelled and waited for", "[state][report]") {
    const auto start = std::chrono::steady_clock::now();
    {
        BackgroundMeasurement m;
        m.start([](Progress& p) { return slow_family(p, 100000); });
    }
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(4));
}
