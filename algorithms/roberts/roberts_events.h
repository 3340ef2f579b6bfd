// SPDX-License-Identifier: MIT
// What Roberts' hidden-line algorithm tells: the convex bodies found, each edge whose two faces both face away
// (removed first), each edge tested against each other body with the part of it that body hides, and each edge
// finished with what is left of it to draw.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "core/phrase.h"

namespace hsr::algo {

struct BodiesFound {
    static constexpr std::string_view kind = "BodiesFound";
    std::uint32_t bodies, edges;
    bool operator==(const BodiesFound&) const = default;
};
// Both faces of the edge face away from the eye: the edge is not drawn, and not tested.
struct EdgeRemoved {
    static constexpr std::string_view kind = "EdgeRemoved";
    std::uint32_t edge, body;
    bool operator==(const EdgeRemoved&) const = default;
};
// The edge against one other body: the part [t0, t1] of it (0 at its first end, 1 at its second) that the body
// hides, where the segment from the point to the eye passes through the body's inside.
struct EdgeTested {
    static constexpr std::string_view kind = "EdgeTested";
    std::uint32_t edge, body, by;
    bool hides;
    double t0, t1;  // the hidden part when hides (world parameter along the edge)
    bool operator==(const EdgeTested&) const = default;
};
struct EdgeFinished {
    static constexpr std::string_view kind = "EdgeFinished";
    std::uint32_t edge;
    double hidden;          // the share of its length hidden, 0 … 1
    std::uint32_t pieces;   // visible pieces left to draw
    bool operator==(const EdgeFinished&) const = default;
};
struct RobertsFinished {
    static constexpr std::string_view kind = "RobertsFinished";
    std::uint32_t drawn, removed;  // edges drawn (some part visible), removed as back edges
    std::uint64_t tests;           // edge-against-body tests
    bool bounded;                  // stopped at the step bound (max_tests)
    bool operator==(const RobertsFinished&) const = default;
};

using RobertsEvent = std::variant<BodiesFound, EdgeRemoved, EdgeTested, EdgeFinished, RobertsFinished>;

Phrase phrase(const RobertsEvent& e);
std::string describe(const RobertsEvent& e);
std::span<const Saying> roberts_sayings();

}  // namespace hsr::algo
