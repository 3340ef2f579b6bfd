// SPDX-License-Identifier: MIT
#include "perspective/transform_events.h"

#include "core/events.h"
#include "core/overloaded.h"

namespace hsr::algo {

namespace {
// What the perspective-transform machine says, each template once (its key is what another language's catalogue
// translates).
namespace say {
constexpr Saying frustum{"transform.frustum", "Eye space: the view volume is a frustum from near {near} to far {far}, the eye at its apex; {points} points. Points on one projection ray have equal x/z and y/z."};
constexpr Saying box{"transform.box", "Eye space: orthographic, the view volume is a box from near {near} to far {far}; {points} points. Projection rays are parallel to z: equal x and y put two points on one ray."};
constexpr Saying normalize{"transform.normalize", "Stage 1, {percent}% done: the volume is scaled to the canonical one (sides at 45°, the far plane at z = −1)."};
constexpr Saying normalize_box{"transform.normalize_box", "Stage 1, {percent}% done: the box is scaled and moved onto the canonical box −1 … 1."};
constexpr Saying warp{"transform.warp", "Stage 2, {percent}% done: the perspective transform pushes the eye away; the projection rays turn toward parallel."};
constexpr Saying warped{"transform.warped", "Stage 2 done: the frustum is the box −1 … 1 and the eye is at infinity; every projection ray is parallel to z."};
constexpr Saying no_warp{"transform.no_warp", "Stage 2: nothing to do. An orthographic volume is a box already; its rays were parallel from the start."};
constexpr Saying point{"transform.point", "Point {point}: eye ({x}, {y}, {z}), w = {w}; divided by w: ({nx}, {ny}, {nz})."};
constexpr Saying behind{"transform.behind", "Point {point} is on or behind the eye's plane (w ≤ 0): left out, as clipping would."};
constexpr Saying too_far{"transform.too_far", "Point {point}: its coordinates are too large for the transform in doubles. Left out."};
constexpr Saying pair{"transform.pair", "Points {a} and {b} lie on one projection ray, both before (x/z, y/z equal) and after (x′, y′ equal): {nearer} is nearer and occludes the other."};
constexpr Saying tie{"transform.tie", "Points {a} and {b} lie on one projection ray, with equal z′: neither occludes the other."};
constexpr Saying apart{"transform.apart", "Points {a} and {b}: not on one projection ray (x/z, y/z: ({rax}, {ray}) and ({rbx}, {rby}))."};
constexpr Saying only_before{"transform.only_before", "Points {a} and {b}: on one projection ray by x/z and y/z, but not by x′ and y′; rounding decided it."};
constexpr Saying only_after{"transform.only_after", "Points {a} and {b}: on one projection ray by x′ and y′, but not by x/z and y/z; rounding decided it."};
constexpr Saying done{"transform.done", "Done: {comparisons} pairs, {pairs} occluding. Before the transform: {before} divisions; after it: {after}, once per point."};
constexpr Saying bound{"transform.bound", "Stopped: the step bound of {comparisons} pairs compared was reached."};
constexpr Saying all[] = {frustum, box, normalize, normalize_box, warp, warped, no_warp, point, behind, too_far, pair, tie, apart, only_before, only_after, done, bound};
}  // namespace say
}  // namespace

std::span<const Saying> transform_sayings() { return say::all; }

Phrase phrase(const TransformEvent& event) {
    const auto n = [](auto v) { return std::to_string(v); };
    const auto f = [](double v) { return format_number(v); };
    const auto percent = [&](double s) { return n(int(std::lround(100 * s))); };
    return std::visit(
        overloaded{
            [&](const VolumeShown& e) {
                return Phrase(e.perspective ? say::frustum : say::box, {{"near", f(e.near)}, {"far", f(e.far)}, {"points", n(e.points)}});
            },
            [&](const WarpStep& e) {
                if (e.stage == 1) return Phrase(e.perspective ? say::normalize : say::normalize_box, {{"percent", percent(e.s)}});
                if (!e.perspective) return Phrase(say::no_warp, {});
                return Phrase(e.s < 1 ? say::warp : say::warped, {{"percent", percent(e.s)}});
            },
            [&](const PointTransformed& e) {
                return Phrase(say::point, {{"point", n(e.point)}, {"x", f(e.x)}, {"y", f(e.y)}, {"z", f(e.z)}, {"w", f(e.w)},
                                           {"nx", f(e.nx)}, {"ny", f(e.ny)}, {"nz", f(e.nz)}});
            },
            [&](const PointLeftOut& e) { return Phrase(e.behind_eye ? say::behind : say::too_far, {{"point", n(e.point)}}); },
            [&](const PairCompared& e) {
                if (e.same_before != e.same_after)
                    return Phrase(e.same_before ? say::only_before : say::only_after, {{"a", n(e.a)}, {"b", n(e.b)}});
                if (!e.same_after)
                    return Phrase(say::apart, {{"a", n(e.a)}, {"b", n(e.b)}, {"rax", f(e.ratio_ax)}, {"ray", f(e.ratio_ay)},
                                               {"rbx", f(e.ratio_bx)}, {"rby", f(e.ratio_by)}});
                if (e.nearer < 0) return Phrase(say::tie, {{"a", n(e.a)}, {"b", n(e.b)}});
                return Phrase(say::pair, {{"a", n(e.a)}, {"b", n(e.b)}, {"nearer", n(e.nearer)}});
            },
            [&](const TransformFinished& e) {
                if (e.bounded) return Phrase(say::bound, {{"comparisons", n(e.comparisons)}});
                return Phrase(say::done, {{"comparisons", n(e.comparisons)}, {"pairs", n(e.pairs)}, {"before", n(e.divisions_before)},
                                          {"after", n(e.divisions_after)}});
            },
        },
        event);
}

std::string describe(const TransformEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
