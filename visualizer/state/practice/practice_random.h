// SPDX-License-Identifier: MIT
// The dice of practice: one exercise's numbers from its seed, the same on every machine and every standard library
// (std::uniform_real_distribution is not specified bit for bit, so a teacher's "exercise 1234" could differ between
// the desktop and the browser build). SplitMix64, and numbers on a grid a student can compute with by hand.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

namespace hsr::viz::practice {

class Dice {
public:
    explicit Dice(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {  // SplitMix64 (Steele, Lea and Flood 2014)
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    // 0 … n − 1 (n ≥ 1)
    int below(int n) { return int(next() % std::uint64_t(n)); }
    // a multiple of `step` in [lo, hi] (both multiples of step)
    double grid(double lo, double hi, double step) {
        const int count = int(std::lround((hi - lo) / step)) + 1;
        return lo + step * below(count);
    }
    bool coin() { return (next() & 1u) != 0; }
    template <class T>
    const T& pick(const std::vector<T>& from) { return from[std::size_t(below(int(from.size())))]; }

private:
    std::uint64_t state_;
};

// The seed of exercise `index` of the series a teacher hands out as `series`: exercise 0 is the series' own seed,
// so "exercise 1234" is the first of series 1234 and the window and the command line agree on it.
inline std::uint64_t exercise_seed(std::uint64_t series, std::uint64_t index) {
    if (index == 0) return series;
    Dice d(series ^ (index * 0xD1B54A32D192ED03ull));
    return d.next();
}

}  // namespace hsr::viz::practice
