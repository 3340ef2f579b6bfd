// SPDX-License-Identifier: MIT
// What the perspective-transform machine tells: the view volume in eye space, the warp of that volume into the
// canonical box step by step, each point's coordinates before and after the divide by w, and each pair of points
// compared for being an occluding pair before the transform (x/z and y/z equal) and after it (x′ and y′ equal).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "core/phrase.h"

namespace hsr::algo {

struct VolumeShown {
    static constexpr std::string_view kind = "VolumeShown";
    bool perspective;
    double near, far;
    std::uint32_t points;
    bool operator==(const VolumeShown&) const = default;
};
// The picture moves a part of the way: stage 1 scales the view volume to the canonical one (a perspective volume
// with sides at 45°, or the box), stage 2 is the perspective transform, the canonical frustum into the box.
struct WarpStep {
    static constexpr std::string_view kind = "WarpStep";
    std::uint32_t stage;  // 1 or 2
    double s;             // 0 … 1 of the stage done
    bool perspective;     // else orthographic: stage 1 is the whole way, stage 2 has nothing to do
    bool operator==(const WarpStep&) const = default;
};
// A point in eye space (x, y, z; the eye at the origin looking down −z), its clip-space w, and after the divide by
// w its normalized device coordinates (x′, y′, z′; the box −1 … 1, z′ = −1 at the near plane).
struct PointTransformed {
    static constexpr std::string_view kind = "PointTransformed";
    std::uint32_t point;
    double x, y, z, w;
    double nx, ny, nz;
    bool operator==(const PointTransformed&) const = default;
};
// A point the transform cannot take: on the eye's plane or behind it (w ≤ 0: the divide would send it through
// infinity and turn "in front of" around; clipping removes it first), or with coordinates too large for doubles.
struct PointLeftOut {
    static constexpr std::string_view kind = "PointLeftOut";
    std::uint32_t point;
    bool behind_eye;  // else a coordinate is not finite after the transform
    bool operator==(const PointLeftOut&) const = default;
};
// Two points compared. Before the transform (perspective): a = b needs x_a/z_a = x_b/z_b and y_a/z_a = y_b/z_b,
// four divisions for the pair; orthographic: x_a = x_b and y_a = y_b. After it: x′_a = x′_b and y′_a = y′_b, no
// division. On one projector, the nearer one (smaller z′) occludes the other.
struct PairCompared {
    static constexpr std::string_view kind = "PairCompared";
    std::uint32_t a, b;
    double ratio_ax, ratio_ay, ratio_bx, ratio_by;  // x/z and y/z (orthographic: x and y) of a and b
    bool same_before, same_after;                   // on one projector, by each test
    std::int32_t nearer;                            // a, b, or −1 when z′ is equal
    bool operator==(const PairCompared&) const = default;
};
struct TransformFinished {
    static constexpr std::string_view kind = "TransformFinished";
    std::uint32_t points, left_out, pairs;       // pairs: occluding pairs found (after the transform)
    std::uint64_t comparisons;                   // pairs of points compared
    std::uint64_t divisions_before, divisions_after;  // what each way divides: 4 per pair, or 3 per point
    std::uint32_t disagreements;                 // pairs where the two tests answer differently
    bool bounded;                                // stopped at the step bound (max_comparisons)
    bool operator==(const TransformFinished&) const = default;
};

using TransformEvent = std::variant<VolumeShown, WarpStep, PointTransformed, PointLeftOut, PairCompared, TransformFinished>;

Phrase phrase(const TransformEvent& e);
std::string describe(const TransformEvent& e);
std::span<const Saying> transform_sayings();

}  // namespace hsr::algo
