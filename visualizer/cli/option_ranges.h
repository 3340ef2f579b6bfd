// SPDX-License-Identifier: MIT
// CLI11 checks for numeric options that refuse what the option cannot take, naming the range in plain numbers: CLI11's
// own read "-5" for an unsigned option as 18446744073709551611, 99999999999999999999 as the largest, and let "nan"
// through CLI::Range.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>

#include "state/arguments.h"

namespace hsr::viz {

inline CLI::Validator whole_from(std::uint64_t lo, std::uint64_t hi) {
    return CLI::Validator([=](std::string& s) { return whole_number_in(s, lo, hi); },
                          "INT " + std::to_string(lo) + " to " + std::to_string(hi));
}

inline CLI::Validator number_from(double lo, double hi) {
    return CLI::Validator([=](std::string& s) { return number_in(s, lo, hi); }, "NUMBER");
}

}  // namespace hsr::viz
