// SPDX-License-Identifier: MIT
// An append-only log of events, stored by type: each alternative of the variant has its own vector, and the log
// keeps one (kind, slot) pair per event. A small event then costs its own size plus 5 bytes, not the size of the
// variant's largest alternative, which is what lets a trace of millions of events stay small.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

namespace hsr::viz {

template <class Variant>
class EventLog;

template <class... Ts>
class EventLog<std::variant<Ts...>> {
public:
    using Event = std::variant<Ts...>;
    static_assert(sizeof...(Ts) < 256, "the kind of an event is stored in one byte");

    void push(const Event& e) {
        std::visit(
            [&](const auto& x) {
                auto& store = std::get<std::vector<std::decay_t<decltype(x)>>>(stores_);
                slots_.push_back(std::uint32_t(store.size()));
                store.push_back(x);
            },
            e);
        kinds_.push_back(std::uint8_t(e.index()));
    }

    [[nodiscard]] Event at(std::size_t k) const { return makers[kinds_[k]](*this, slots_[k]); }
    [[nodiscard]] std::size_t size() const { return kinds_.size(); }
    [[nodiscard]] bool empty() const { return kinds_.empty(); }

    // Bytes held (capacity, not size: what the process really pays).
    [[nodiscard]] std::size_t bytes() const {
        std::size_t b = kinds_.capacity() * sizeof(std::uint8_t) + slots_.capacity() * sizeof(std::uint32_t);
        std::apply([&](const auto&... store) { ((b += store.capacity() * sizeof(store[0])), ...); }, stores_);
        return b;
    }

    void shrink_to_fit() {
        kinds_.shrink_to_fit();
        slots_.shrink_to_fit();
        std::apply([](auto&... store) { (store.shrink_to_fit(), ...); }, stores_);
    }

private:
    template <std::size_t I>
    static Event make(const EventLog& log, std::uint32_t slot) {
        return Event(std::in_place_index<I>, std::get<I>(log.stores_)[slot]);
    }
    using Maker = Event (*)(const EventLog&, std::uint32_t);
    static constexpr std::array<Maker, sizeof...(Ts)> makers = []<std::size_t... I>(std::index_sequence<I...>) {
        return std::array<Maker, sizeof...(Ts)>{&make<I>...};
    }(std::index_sequence_for<Ts...>{});

    std::tuple<std::vector<Ts>...> stores_;
    std::vector<std::uint8_t> kinds_;
    std::vector<std::uint32_t> slots_;
};

}  // namespace hsr::viz
