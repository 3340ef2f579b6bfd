// SPDX-License-Identifier: MIT
#include "geometry/union_find.h"

#include <numeric>

namespace hsr::algo {

UnionFind::UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t{0}); }

std::size_t UnionFind::find(std::size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];  // each visited item skips to its grandparent
    return x;
}

void UnionFind::join(std::size_t a, std::size_t b) { parent_[find(a)] = find(b); }

}  // namespace hsr::algo
