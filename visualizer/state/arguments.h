// SPDX-License-Identifier: MIT
// Command-line values read strictly: a size is two whole numbers in range joined by an x ("1280x800"), a point three
// finite numbers joined by commas. Anything else (sscanf's "4294967297x1" read as 1×1, "x", "nan,nan,nan") is
// refused, so a typo is a usage error and never a silent other picture.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include <glm/vec3.hpp>

namespace hsr::viz {

// WIDTHxHEIGHT, each from 1 to `largest`.
std::optional<std::pair<int, int>> parse_size(const std::string& text, int largest = 16384);
// X,Y,Z, each finite and within ±1e100 (the scenes' own bound).
std::optional<glm::dvec3> parse_point(const std::string& text);

// A whole number from `lo` to `hi` written in decimal digits: "" when it is one, else why not, naming the range in
// plain numbers ("-5", "1e3", "99999999999999999999" and "nan" are refused, never wrapped or rounded).
std::string whole_number_in(const std::string& text, std::uint64_t lo, std::uint64_t hi);
// A finite number from `lo` to `hi`: "" or why not ("nan", "inf" and "1x" are refused).
std::string number_in(const std::string& text, double lo, double hi);

}  // namespace hsr::viz
