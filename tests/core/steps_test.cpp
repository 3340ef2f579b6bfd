// SPDX-License-Identifier: MIT
#include <memory>
#include <stdexcept>
#include <variant>
#include <string>
#include <vector>

#include "catch.h"
#include "core/events.h"
#include "core/steps.h"

using hsr::algo::Steps;

namespace {

// Records when the body runs, so a test can see that nothing runs before it is pulled.
Steps<int, std::string> counting(std::vector<std::string>* checkpoints, int n) {
    checkpoints->push_back("started");
    for (int i = 0; i < n; ++i) {
        checkpoints->push_back("before " + std::to_string(i));
        co_yield i;
        checkpoints->push_back("after " + std::to_string(i));
    }
    co_return "counted " + std::to_string(n);
}

// Recursion as nested generators: the events of depth d are d, then the child's, then −d.
Steps<int, int> nested(int depth) {
    co_yield depth;
    int below = 0;
    if (depth > 0) {
        auto child = nested(depth - 1);
        for (const int& e : child) co_yield e;
        below = child.result();
    }
    co_yield -depth;
    co_return below + 1;
}

Steps<int, int> throwing_after(int n) {
    for (int i = 0; i < n; ++i) co_yield i;
    throw std::runtime_error("boom");
}

}  // namespace

TEST_CASE("a Steps machine is lazy: nothing runs before the first pull", "[core][steps]") {
    std::vector<std::string> checkpoints;
    auto machine = counting(&checkpoints, 2);
    CHECK(checkpoints.empty());
    CHECK_FALSE(machine.done());

    const int* e = machine.next();
    REQUIRE(e != nullptr);
    CHECK(*e == 0);
    CHECK(checkpoints == std::vector<std::string>{"started", "before 0"});

    e = machine.next();
    REQUIRE(e != nullptr);
    CHECK(*e == 1);
    CHECK(checkpoints.back() == "before 1");

    CHECK(machine.next() == nullptr);
    CHECK(machine.done());
    CHECK(checkpoints.back() == "after 1");
    CHECK(machine.result() == "counted 2");
    CHECK(machine.next() == nullptr);  // pulling a finished machine stays finished
}

TEST_CASE("a Steps machine gives its co_return result only once finished", "[core][steps]") {
    std::vector<std::string> checkpoints;
    auto machine = counting(&checkpoints, 1);
    CHECK_THROWS_AS(machine.result(), std::logic_error);
    machine.next();
    CHECK_THROWS_AS(machine.result(), std::logic_error);
    CHECK(machine.run_to_end() == "counted 1");
}

TEST_CASE("a machine with no events still returns its result", "[core][steps]") {
    std::vector<std::string> checkpoints;
    auto machine = counting(&checkpoints, 0);
    CHECK(machine.next() == nullptr);
    CHECK(machine.result() == "counted 0");
}

TEST_CASE("nested machines forward their child's events in order and return its result", "[core][steps]") {
    auto machine = nested(3);
    std::vector<int> events;
    for (const int& e : machine) events.push_back(e);
    CHECK(events == std::vector<int>{3, 2, 1, 0, 0, -1, -2, -3});
    CHECK(machine.result() == 4);
}

TEST_CASE("an exception thrown in the body is rethrown from next()", "[core][steps]") {
    auto machine = throwing_after(2);
    CHECK(*machine.next() == 0);
    CHECK(*machine.next() == 1);
    CHECK_THROWS_WITH(machine.next(), "boom");
    CHECK(machine.done());
    CHECK(machine.next() == nullptr);
    CHECK_THROWS_AS(machine.result(), std::logic_error);
}

TEST_CASE("an exception in a nested machine reaches the outer caller", "[core][steps]") {
    auto outer = [](int n) -> Steps<int, int> {
        auto inner = throwing_after(n);
        for (const int& e : inner) co_yield e * 10;
        co_return 0;
    }(1);
    CHECK(*outer.next() == 0);
    CHECK_THROWS_WITH(outer.next(), "boom");
}

TEST_CASE("a Steps machine is move-only and a moved-from machine is finished", "[core][steps]") {
    STATIC_REQUIRE_FALSE(std::is_copy_constructible_v<Steps<int, int>>);
    STATIC_REQUIRE(std::is_move_constructible_v<Steps<int, int>>);
    auto a = nested(1);
    CHECK(*a.next() == 1);
    auto b = std::move(a);
    CHECK(a.done());
    CHECK(a.next() == nullptr);
    CHECK(*b.next() == 0);  // b continues where a was
    a = std::move(b);
    CHECK(*a.next() == 0);
}

TEST_CASE("destroying an unfinished machine runs no more of its body", "[core][steps]") {
    std::vector<std::string> checkpoints;
    {
        auto machine = counting(&checkpoints, 5);
        machine.next();
    }
    CHECK(checkpoints == std::vector<std::string>{"started", "before 0"});
}

namespace {

struct Owning {  // an event with a non-trivial member, like the BSP's PolygonSplit
    std::shared_ptr<const int> value;
    bool operator==(const Owning&) const = default;
};
using OwningEvent = std::variant<int, Owning>;

Steps<OwningEvent, int> owning_events(std::shared_ptr<const int> shared, int n) {
    for (int i = 0; i < n; ++i) {
        if (i % 2 == 0) {
            auto copy = shared;
            const OwningEvent e = Owning{std::move(copy)};  // by name: see the top of steps.h
            co_yield e;
        } else {
            co_yield i;
        }
    }
    co_return n;
}

Steps<OwningEvent, int> forwarding(std::shared_ptr<const int> shared) {
    auto child = owning_events(std::move(shared), 6);
    for (const auto& e : child) co_yield e;
    co_return child.result();
}

}  // namespace

TEST_CASE("events with non-trivial members are destroyed exactly once, also when forwarded", "[core][steps]") {
    auto shared = std::make_shared<const int>(42);
    {
        auto machine = forwarding(shared);
        int owning = 0;
        while (const OwningEvent* e = machine.next()) {
            if (const auto* o = std::get_if<Owning>(e)) {
                ++owning;
                CHECK(*o->value == 42);
            }
        }
        CHECK(owning == 3);
        CHECK(machine.result() == 6);
    }
    CHECK(shared.use_count() == 1);  // every copy made for an event is gone, none released twice
}

TEST_CASE("a temporary machine's result is moved out, so iterating it does not dangle", "[core][steps]") {
    const auto digits = []() -> Steps<int, std::vector<int>> {
        co_yield 0;
        co_return std::vector<int>{1, 2, 3};
    };
    int sum = 0;
    for (int d : digits().run_to_end()) sum += d;  // the Steps temporary ends before the loop body runs
    CHECK(sum == 6);
    STATIC_REQUIRE(std::is_same_v<decltype(digits().run_to_end()), std::vector<int>>);
}

TEST_CASE("numbers in sentences: rounding noise below 1e-12 of the scale prints as 0", "[core][format]") {
    using hsr::algo::format_number;
    CHECK(format_number(1.4802973661668754e-17, 1.0) == "0");     // lesson 11's −a/c of a polygon facing the eye
    CHECK(format_number(-1.1102230246251565e-16, 0.612716) == "0");  // lesson 16's x extent
    CHECK(format_number(-0.0, 1.0) == "0");
    CHECK(format_number(1e-9, 1.0) == "1e-09");                    // small, but a value: kept
    CHECK(format_number(1e-15, 1e-6) == "1e-15");                  // tiny numbers of a tiny scale are values
    CHECK(format_number(0.25, 1.0) == "0.25");
}
