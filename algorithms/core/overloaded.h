// SPDX-License-Identifier: MIT
// The usual visitor helper for std::visit over an event variant (clang 14 needs the deduction guide).
#pragma once

namespace hsr {

template <class... Fs>
struct overloaded : Fs... {
    using Fs::operator()...;
};
template <class... Fs>
overloaded(Fs...) -> overloaded<Fs...>;

}  // namespace hsr
