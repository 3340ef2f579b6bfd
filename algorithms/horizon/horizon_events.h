// SPDX-License-Identifier: MIT
// The floating horizon's events: a curve begins, each of its points is tested against the two horizons, the curve
// is drawn where it showed. Every number a view or a sentence needs is in the event (the horizons before the test).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "core/phrase.h"

namespace hsr::algo {

// Where a point of a curve lies against the horizons drawn so far.
enum class Sight : std::uint8_t { above, below, hidden };
std::string_view to_string(Sight s);

struct CurveStarted {
    static constexpr std::string_view kind = "CurveStarted";
    int row;     // 0: the nearest curve
    double z;    // world units from the nearest row
    bool operator==(const CurveStarted&) const = default;
};
struct PointTested {
    static constexpr std::string_view kind = "PointTested";
    int row, column;        // the curve, and the screen column it is sampled at
    double x, height;       // world: the column's centre, the curve's height there (linear between samples)
    double y;               // screen: height · cos(elevation) + z · sin(elevation)
    bool first;             // no horizon yet (the nearest curve): upper and lower below are meaningless
    double upper, lower;    // screen: the horizons at this column before the test
    Sight sight;            // above the upper, below the lower, or between them: hidden
    bool operator==(const PointTested&) const = default;
};
struct CurveDrawn {
    static constexpr std::string_view kind = "CurveDrawn";
    int row;
    int above, below, hidden;  // its columns of each sight
    bool operator==(const CurveDrawn&) const = default;
};
struct HorizonFinished {
    static constexpr std::string_view kind = "HorizonFinished";
    std::uint64_t visible, hidden;  // points of all curves
    bool operator==(const HorizonFinished&) const = default;
};
using HorizonEvent = std::variant<CurveStarted, PointTested, CurveDrawn, HorizonFinished>;

// What an event says, as a template with named values (core/phrase.h), and in English.
Phrase phrase(const HorizonEvent& e);
std::string describe(const HorizonEvent& e);
std::span<const Saying> horizon_sayings();  // every template the floating horizon says

}  // namespace hsr::algo
