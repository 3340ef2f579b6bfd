// SPDX-License-Identifier: MIT
// Every template the machines say (core/phrase.h), family by family: what a language's catalogue translates under
// [machine], and what the test over the catalogues checks them against.
#pragma once

#include <span>
#include <vector>

#include "core/phrase.h"

namespace hsr::algo {

std::vector<std::span<const Saying>> machine_sayings();

}  // namespace hsr::algo
