// SPDX-License-Identifier: MIT
// What the scan-line algorithms tell: the edge table, each scan line, edges entering and leaving the active edge
// table, each edge crossed on the line (the polygon's in/out flag flips), and the spans coloured. The classic one
// (no z-buffer) also tells where it compares the depths of the polygons in, and where two of them pierce each other.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <span>
#include <variant>

#include "core/phrase.h"
#include "scene/scene.h"

namespace hsr::algo {

struct EdgeTableBuilt {
    static constexpr std::string_view kind = "EdgeTableBuilt";
    std::uint32_t edges, polygons;  // non-horizontal edges; polygons with area on the screen
    bool operator==(const EdgeTableBuilt&) const = default;
};
struct ScanLineStarted {
    static constexpr std::string_view kind = "ScanLineStarted";
    int y;
    bool operator==(const ScanLineStarted&) const = default;
};
struct EdgeEntered {
    static constexpr std::string_view kind = "EdgeEntered";
    std::uint32_t edge, polygon;  // into the edge table; into the polygons
    int y;
    double x;  // where it crosses the line's centre, pixels
    bool operator==(const EdgeEntered&) const = default;
};
struct EdgeLeft {
    static constexpr std::string_view kind = "EdgeLeft";
    std::uint32_t edge, polygon;
    int y;
    bool operator==(const EdgeLeft&) const = default;
};
struct EdgeCrossed {
    static constexpr std::string_view kind = "EdgeCrossed";
    std::uint32_t edge, polygon;
    int y;
    double x;
    bool entering;  // the polygon's in/out flag after the crossing
    bool classic = false;  // told by the classic scan line (no line z-buffer takes the span when it goes out)
    bool operator==(const EdgeCrossed&) const = default;
};
// Classic scan line: where a span begins with two or more polygons in, their plane equations are evaluated there.
struct DepthsCompared {
    static constexpr std::string_view kind = "DepthsCompared";
    int y;
    double x;                  // the pixel centre compared at
    std::uint32_t in;          // polygons in
    std::int32_t nearest;      // the nearest of them (on a tie, the lower index)
    double depth;              // its window depth there
    std::int32_t next;         // the next nearest
    double next_depth;
    bool operator==(const DepthsCompared&) const = default;
};
// Classic scan line: before the next intersection, polygon `now` comes nearer than `was` (they pierce each other):
// an extra intersection at x, where their depths are equal; `now` is seen from pixel `pixel` on.
struct PiercingFound {
    static constexpr std::string_view kind = "PiercingFound";
    int y;
    double x;
    std::int32_t was, now;
    int pixel;
    bool operator==(const PiercingFound&) const = default;
};
struct SpanColored {
    static constexpr std::string_view kind = "SpanColored";
    int y, x_begin, x_end;   // pixels [x_begin, x_end) of line y
    std::int32_t polygon;    // the one the line's z-buffer (classic: the nearest in) kept there, −1 for background
    SceneId id;
    bool operator==(const SpanColored&) const = default;
};
struct ScanFinished {
    static constexpr std::string_view kind = "ScanFinished";
    std::uint32_t lines;
    std::uint64_t spans;
    bool operator==(const ScanFinished&) const = default;
};
struct ScanStepBoundReached {
    static constexpr std::string_view kind = "ScanStepBoundReached";
    std::uint64_t max_crossings;
    bool operator==(const ScanStepBoundReached&) const = default;
};

using ScanLineEvent = std::variant<EdgeTableBuilt, ScanLineStarted, EdgeEntered, EdgeLeft, EdgeCrossed, DepthsCompared,
                                   PiercingFound, SpanColored, ScanFinished, ScanStepBoundReached>;

// What an event says, as a template with named values (core/phrase.h), and in English.
Phrase phrase(const ScanLineEvent& e);
std::string describe(const ScanLineEvent& e);
std::span<const Saying> scanline_sayings();  // every template the scan-line machine says

}  // namespace hsr::algo
