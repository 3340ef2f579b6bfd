// SPDX-License-Identifier: MIT
// Union–find (disjoint sets) over the items 0 … n−1: which group an item is in, as the group's root, with the path
// halved on every look-up so that chains stay short.
#pragma once

#include <cstddef>
#include <vector>

namespace hsr::algo {

class UnionFind {
public:
    explicit UnionFind(std::size_t n);
    // The root of x's group: two items are in one group when their roots are equal.
    std::size_t find(std::size_t x);
    // Puts a's group into b's (a's root now points at b's).
    void join(std::size_t a, std::size_t b);

private:
    std::vector<std::size_t> parent_;  // an item's parent; a root is its own
};

}  // namespace hsr::algo
