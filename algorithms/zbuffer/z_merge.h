// SPDX-License-Identifier: MIT
// The lecture's z-merge of two frame/depth buffer pairs (f_a, z_a) and (f_b, z_b) of two parts of a scene:
//
//   for (x = 0; x < XRES; x++)
//     for (y = 0; y < YRES; y++) {
//       Fc[x, y] = (Za[x, y] nearer than Zb[x, y]) ? Fa[x, y] : Fb[x, y];
//       Zc[x, y] = (Za[x, y] nearer than Zb[x, y]) ? Za[x, y] : Zb[x, y];
//     }
//
// The lecture writes `Za > Zb` because its depths decrease with distance; our codes grow with distance in every
// format (depth_format.h), so nearer is smaller. On a tie b wins, as in the lecture.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <span>
#include <variant>

#include "core/phrase.h"
#include "core/steps.h"
#include "zbuffer/zbuffer_fill.h"

namespace hsr::algo {

struct PixelMerged {
    static constexpr std::string_view kind = "PixelMerged";
    int x, y;
    std::uint32_t depth_a, depth_b;  // the two codes
    bool from_a;                     // a was nearer
    bool operator==(const PixelMerged&) const = default;
};
struct MergeFinished {
    static constexpr std::string_view kind = "MergeFinished";
    std::uint64_t from_a, from_b;  // pixels showing a polygon of part A, of part B
    std::uint64_t background;      // pixels where neither part has a polygon (two far planes: B's stays)
    bool operator==(const MergeFinished&) const = default;
};
using ZMergeEvent = std::variant<PixelMerged, MergeFinished>;

// The buffers must have the same size (InvalidInput otherwise). The result's polygon indices are a's or b's own.
Steps<ZMergeEvent, FrameDepth> z_merge_steps(FrameDepth a, FrameDepth b);

// What an event says, as a template with named values (core/phrase.h), and in English.
Phrase phrase(const ZMergeEvent& e);
std::string describe(const ZMergeEvent& e);
std::span<const Saying> zmerge_sayings();  // every template the z-merge says

}  // namespace hsr::algo
