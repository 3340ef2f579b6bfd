// SPDX-License-Identifier: MIT
#include "zbuffer/z_merge.h"

#include "core/numeric.h"
#include "core/overloaded.h"
#include "core/phrase.h"

namespace hsr::algo {

Steps<ZMergeEvent, FrameDepth> z_merge_steps(FrameDepth a, FrameDepth b) {
    if (a.image.width != b.image.width || a.image.height != b.image.height)
        throw InvalidInput("z-merge: the two buffers differ in size");
    FrameDepth c = b;
    std::uint64_t from_a = 0, background = 0;
    const int w = a.image.width, h = a.image.height;
    for (int x = 0; x < w; ++x)
        for (int y = 0; y < h; ++y) {
            const std::size_t k = std::size_t(y) * std::size_t(w) + std::size_t(x);
            // Take a where it is nearer, else keep b
            const bool a_nearer = a.depth[k] < b.depth[k];
            co_yield PixelMerged{x, y, a.depth[k], b.depth[k], a_nearer};
            if (!a_nearer) {
                background += b.polygon[k] < 0;
                continue;
            }
            ++from_a;
            c.depth[k] = a.depth[k];
            c.polygon[k] = a.polygon[k];
            c.image.ids[k] = a.image.ids[k];
            for (std::size_t ch = 0; ch < 3; ++ch) c.image.rgb[3 * k + ch] = a.image.rgb[3 * k + ch];
        }
    c.tested = a.tested + b.tested, c.written = a.written + b.written;
    co_yield MergeFinished{from_a, std::uint64_t(w) * std::uint64_t(h) - from_a - background, background};
    co_return c;
}

namespace {
// What the z-merge says (its key is what another language's catalogue translates).
namespace say {
constexpr Saying from_a{"zmerge.from_a", "Pixel ({x}, {y}): {a} < {b}, so part A is nearer and gives colour and depth."};
constexpr Saying from_b{"zmerge.from_b", "Pixel ({x}, {y}): {a} ≥ {b}, so part B's colour and depth stay."};
constexpr Saying merged{"zmerge.merged", "Merged: {from_a} pixels from part A, {from_b} from part B, {background} background in both."};
constexpr Saying all[] = {from_a, from_b, merged};
}  // namespace say
}  // namespace

std::span<const Saying> zmerge_sayings() { return say::all; }

Phrase phrase(const ZMergeEvent& event) {
    const auto n = [](auto v) { return std::to_string(v); };
    return std::visit(overloaded{
                          [&](const PixelMerged& e) {
                              return Phrase(e.from_a ? say::from_a : say::from_b,
                                            {{"x", n(e.x)}, {"y", n(e.y)}, {"a", n(e.depth_a)}, {"b", n(e.depth_b)}});
                          },
                          [&](const MergeFinished& e) { return Phrase(say::merged, {{"from_a", n(e.from_a)}, {"from_b", n(e.from_b)}, {"background", n(e.background)}});
                          },
                      },
                      event);
}

std::string describe(const ZMergeEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
