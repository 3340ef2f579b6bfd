// SPDX-License-Identifier: MIT
// What every family's events share: each event struct names its kind (`static constexpr std::string_view kind`),
// and sentences print numbers the same way.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

namespace hsr::algo {

// "OutcodeComputed", "PolygonSplit", …: the kind of whichever event the variant holds.
template <class... Events>
std::string_view kind_of(const std::variant<Events...>& e) {
    return std::visit([](const auto& event) { return std::decay_t<decltype(event)>::kind; }, e);
}

// A number in a sentence: six significant digits, no trailing zeros ("0.25", "1e-09", "-4.69254").
inline std::string format_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// A number computed from numbers of size `scale`: what lies below 1e-12 of the scale is rounding, not a value, and
// prints as 0 (a depth that changes by 1.48e-17 per pixel does not change).
inline std::string format_number(double v, double scale) {
    return format_number(std::abs(v) < 1e-12 * std::abs(scale) ? 0.0 : v);
}

}  // namespace hsr::algo
