// SPDX-License-Identifier: MIT
// The one include of Catch2, v2 (Debian 12) or v3 (Debian 13): the tests are written against v2's names, and v3's
// renames are mapped back here (Approx moved into Catch::, the string matchers into Catch::Matchers:: with Contains
// now ContainsSubstring).
#pragma once
#if __has_include(<catch2/catch_all.hpp>)
#include <catch2/catch_all.hpp>
#include <string>
using Catch::Approx;
namespace Catch {
inline Matchers::StringContainsMatcher Contains(const std::string& text, CaseSensitive cases = CaseSensitive::Yes) {
    return Matchers::ContainsSubstring(text, cases);
}
using Matchers::StartsWith;
using Matchers::EndsWith;
}  // namespace Catch
#else
#include <catch2/catch.hpp>
#endif
