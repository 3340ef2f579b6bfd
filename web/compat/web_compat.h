// SPDX-License-Identifier: MIT
// What C++20 gives the desktop build and Debian 12's emscripten 3.1.6 (its libc++) lacks, included before every
// source of the web build (-include, web/CMakeLists.txt). Nothing here changes what the code means.
#pragma once

#include <bit>
#include <type_traits>

#if !defined(__cpp_lib_bit_cast)
namespace std {
template <class To, class From>
    requires(sizeof(To) == sizeof(From) && is_trivially_copyable_v<To> && is_trivially_copyable_v<From>)
constexpr To bit_cast(const From& from) noexcept {
    return __builtin_bit_cast(To, from);
}
}  // namespace std
#endif
