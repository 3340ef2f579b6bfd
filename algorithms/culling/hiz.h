// SPDX-License-Identifier: MIT
// Hierarchical visibility with a hierarchical z-buffer (the lecture: Greene's Z-pyramid over an object-space
// octree):
//
//   Cull_or_Render(N):   if N's box is outside the view frustum, or isOccluded(N, Zp): return
//                        for each primitive p in N: render p and update Zp
//                        for each child C of N in front-to-back order: Cull_or_Render(C)
//   isOccluded(g, Zp):   nearZ = the nearest depth of g's box
//                        if nearZ is behind Zp's texel: return true
//                        else return isOccluded(g, each of the texel's four children over g's footprint)
//
// Level 0 of the pyramid is the depth buffer; each level above holds, per texel, the farthest depth of the (up to
// four) texels below it. Sizes need not be powers of two: a level is ⌈w/2⌉ × ⌈h/2⌉ and a texel on an odd edge
// has fewer children, so the pyramid stays conservative. A box reaching behind the near plane is never occluded.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/phrase.h"
#include "core/steps.h"
#include "culling/hierarchy.h"
#include "zbuffer/zbuffer_fill.h"

namespace hsr::algo {

struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // [x0, x1) × [y0, y1), y down
    [[nodiscard]] bool empty() const { return x1 <= x0 || y1 <= y0; }
};

class ZPyramid {
public:
    ZPyramid(const std::vector<std::uint32_t>& depth, int width, int height);
    // Level 0 takes the depths in `rect` from `depth`; the levels above are recomputed over it.
    void update(const std::vector<std::uint32_t>& depth, PixelRect rect);
    // The lecture's isOccluded for a footprint (level-0 pixels) whose nearest depth code is `near`.
    [[nodiscard]] bool occluded(PixelRect footprint, std::uint32_t near, std::uint32_t* texels_tested = nullptr) const;
    [[nodiscard]] std::size_t levels() const { return levels_.size(); }
    [[nodiscard]] int width(std::size_t level) const { return levels_[level].width; }
    [[nodiscard]] int height(std::size_t level) const { return levels_[level].height; }
    [[nodiscard]] std::uint32_t at(std::size_t level, int x, int y) const;

private:
    struct Level {
        int width, height;
        std::vector<std::uint32_t> depth;  // the farthest code below each texel
    };
    std::vector<Level> levels_;  // 0: the depth buffer; the last is 1 × 1
    bool occluded(std::size_t level, int x, int y, PixelRect footprint, std::uint32_t near, std::uint32_t& tested) const;
};

// A box's footprint on the screen and its nearest depth code; `reaches_eye` when a corner is behind the near plane
// (the footprint is then the whole screen and the box is taken as visible).
struct BoxOnScreen {
    PixelRect footprint;
    std::uint32_t near = 0;
    bool reaches_eye = false;
};
BoxOnScreen box_on_screen(const Aabb& box, const Scene& scene, const ZBufferOptions& options);

enum class HizOutcome : std::uint8_t { outside_frustum, occluded, rendered };
struct HizNodeTested {
    static constexpr std::string_view kind = "HizNodeTested";
    std::uint32_t node;
    HizOutcome outcome;
    PixelRect footprint;
    std::uint32_t near, texels_tested, primitives_rendered, subtree_primitives;
    bool operator==(const HizNodeTested& o) const {
        return node == o.node && outcome == o.outcome && near == o.near && texels_tested == o.texels_tested;
    }
};
struct HizFinished {
    static constexpr std::string_view kind = "HizFinished";
    std::uint32_t nodes, occluded_nodes, rendered, left_out;  // primitives rendered and left out
    bool operator==(const HizFinished&) const = default;
};
using HizEvent = std::variant<HizNodeTested, HizFinished>;
// What an event says, as a template with named values (core/phrase.h), and in English.
Phrase phrase(const HizEvent& e);
std::string describe(const HizEvent& e);
std::span<const Saying> hiz_sayings();

struct HizResult {
    FrameDepth buffers;
    std::vector<std::uint8_t> rendered;  // per primitive
    std::uint32_t occluded_nodes = 0, outside_nodes = 0, texels_tested = 0;
    std::uint32_t drawn_first = 0;  // of the rendered, those drawn before the walk (frame-to-frame coherence)
};

// Cull_or_Render over an octree (or BVH) of the scene's polygons. The scene and hierarchy must outlive the machine.
// `enabled` (per polygon; empty: all) leaves out what earlier stages culled. `draw_first` (per polygon; empty:
// none) is frame-to-frame coherence, Greene's: what the previous frame saw is rendered before the walk, and the
// pyramid built from it, so the walk starts against a nearly full pyramid. It stays conservative: whatever the
// previous frame saw, what is tested is tested against depth really drawn this frame.
Steps<HizEvent, HizResult> hiz_render(const Scene* scene, const Hierarchy* hierarchy, ZBufferOptions options,
                                      std::vector<std::uint8_t> enabled = {}, std::vector<std::uint8_t> draw_first = {});

}  // namespace hsr::algo
