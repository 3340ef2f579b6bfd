// SPDX-License-Identifier: MIT
// Work split over the machine's cores in contiguous chunks, for the batch stages that no view steps through (the
// projection of a whole scene, the z-buffer's polygon-level fill and its image). Small jobs stay on the calling
// thread: starting threads costs more than they would save.
#pragma once

#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace hsr::algo {

// How many threads the batch stages use: the cores online, at most 8.
inline unsigned worker_count() { return std::clamp(std::thread::hardware_concurrency(), 1u, 8u); }

// Calls chunk(begin, end, k) for consecutive chunks k = 0, 1, … covering [0, count), each on its own thread, with
// at least `least_per_chunk` items in a chunk. An exception thrown in a chunk is rethrown here; when several throw,
// the one of the earliest chunk, so that the error named is the one a loop in order would have met first.
template <typename Chunk>
void for_each_chunk(std::size_t count, std::size_t least_per_chunk, Chunk&& chunk) {
    const std::size_t chunks = std::clamp<std::size_t>(count / std::max<std::size_t>(least_per_chunk, 1), 1, worker_count());
    if (chunks == 1) {
        chunk(std::size_t(0), count, std::size_t(0));
        return;
    }
    std::vector<std::exception_ptr> errors(chunks);
    const auto run = [&](std::size_t k) {
        try {
            chunk(count * k / chunks, count * (k + 1) / chunks, k);
        } catch (...) {
            errors[k] = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    for (std::size_t k = 1; k < chunks; ++k) pool.emplace_back(run, k);
    run(0);
    for (std::thread& t : pool) t.join();
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

}  // namespace hsr::algo
