// SPDX-License-Identifier: MIT
#include "zbuffer/z_merge.h"

#include "core/numeric.h"
#include "core/overloaded.h"

namespace hsr::algo {

Steps<ZMergeEvent, FrameDepth> z_merge_steps(FrameDepth a, FrameDepth b) {
    if (a.image.width != b.image.width || a.image.height != b.image.height)
        throw InvalidInput("z-merge: the two buffers differ in size");
    FrameDepth c = b;
    std::uint64_t from_a = 0;
    const int w = a.image.width, h = a.image.height;
    for (int x = 0; x < w; ++x)
        for (int y = 0; y < h; ++y) {
            const std::size_t k = std::size_t(y) * std::size_t(w) + std::size_t(x);
            // Take a where it is nearer, else keep b
            const bool a_nearer = a.depth[k] < b.depth[k];
            co_yield PixelMerged{x, y, a.depth[k], b.depth[k], a_nearer};
            if (!a_nearer) continue;
            ++from_a;
            c.depth[k] = a.depth[k];
            c.polygon[k] = a.polygon[k];
            c.image.ids[k] = a.image.ids[k];
            for (std::size_t ch = 0; ch < 3; ++ch) c.image.rgb[3 * k + ch] = a.image.rgb[3 * k + ch];
        }
    c.tested = a.tested + b.tested, c.written = a.written + b.written;
    co_yield MergeFinished{from_a, std::uint64_t(w) * std::uint64_t(h) - from_a};
    co_return c;
}

std::string describe(const ZMergeEvent& event) {
    return std::visit(overloaded{
                          [](const PixelMerged& e) {
                              return "Pixel (" + std::to_string(e.x) + ", " + std::to_string(e.y) + "): " +
                                     std::to_string(e.depth_a) + (e.from_a ? " < " : " ≥ ") + std::to_string(e.depth_b) +
                                     (e.from_a ? ", so part A is nearer and gives colour and depth."
                                               : ", so part B's colour and depth stay.");
                          },
                          [](const MergeFinished& e) {
                              return "Merged: " + std::to_string(e.from_a) + " pixels from part A, " +
                                     std::to_string(e.from_b) + " from part B.";
                          },
                      },
                      event);
}

}  // namespace hsr::algo
