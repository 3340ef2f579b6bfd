// SPDX-License-Identifier: MIT
// Random numbers that are the same with every compiler and standard library, so that a generated city or field, a
// random scene, a preset and a report's sampled rays are the same on the desktop (g++ and libstdc++) and in the
// browser (clang and libc++). std::mt19937 is specified bit for bit; std::uniform_real_distribution,
// std::uniform_int_distribution and std::shuffle are not, and the two libraries draw different numbers from one seed
// (lesson 22's field of 900 objects played 78 steps on the desktop and 62 in the page). Callers draw into named
// variables, one statement after another: the order in which a function's arguments are evaluated is unspecified
// too (g++ goes right to left, clang left to right).
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace hsr::algo {

class PortableRandom {
public:
    explicit PortableRandom(std::uint32_t seed) : engine_(seed) {}

    // In [0, 1), from 53 random bits (the Mersenne Twister authors' genrand_res53).
    double unit() {
        const std::uint32_t high = next() >> 5, low = next() >> 6;
        return (high * 67108864.0 + low) * (1.0 / 9007199254740992.0);
    }
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    // lo … hi, both included; for spans far below 2^32 (a colour channel, a count of corners), where the modulo's
    // bias is negligible.
    int integer(int lo, int hi) { return lo + int(next() % std::uint32_t(hi - lo + 1)); }
    // Fisher–Yates.
    template <class T>
    void shuffle(std::vector<T>& v) {
        for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[std::size_t(next()) % i]);
    }
    // The engine's next 32 bits (its result type is wider on some platforms).
    std::uint32_t next() { return std::uint32_t(engine_()); }

private:
    std::mt19937 engine_;
};

}  // namespace hsr::algo
