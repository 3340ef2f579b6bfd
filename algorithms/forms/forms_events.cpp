// SPDX-License-Identifier: MIT
#include "forms/forms_events.h"

#include <cmath>

#include "core/events.h"
#include "core/overloaded.h"

namespace hsr::algo {

namespace {
// What the general forms say, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying shown{"forms.shown", "A floor plan of {primitives} segments seen in perspective; the image is one row of {pixels} pixels. Object space first, then image space, on the same scene."};
constexpr Saying shown_ortho{"forms.shown_ortho", "A floor plan of {primitives} segments seen orthographically; the image is one row of {pixels} pixels. Object space first, then image space, on the same scene."};
constexpr Saying projected{"forms.projected", "Segment {id} projects onto the image line from u = {from} to {to}."};
constexpr Saying out_of_view{"forms.out_of_view", "Segment {id} has no part in view: it is left out before either form starts."};
constexpr Saying hides{"forms.hides", "Object space: segment {other} is nearer than segment {id} from u = {from} to {to} and hides that part of it."};
constexpr Saying behind{"forms.behind", "Object space: segment {other} overlaps segment {id} on the image but lies behind it there."};
constexpr Saying apart{"forms.apart", "Object space: segments {id} and {other} do not overlap on the image."};
constexpr Saying visible{"forms.visible", "The visible part of segment {id}: {parts}, {percent}% of its image."};
constexpr Saying hidden{"forms.hidden", "Segment {id} is hidden entirely: nothing to render."};
constexpr Saying rendered{"forms.rendered", "Segment {id} renders its visible part: pixels {pixels}."};
constexpr Saying no_pixel{"forms.no_pixel", "Segment {id}'s visible part covers no pixel centre: no pixel drawn."};
constexpr Saying closest{"forms.closest", "Image space, pixel {pixel}: the projector meets segment {id} at depth {depth}, the closest so far."};
constexpr Saying farther{"forms.farther", "Image space, pixel {pixel}: the projector meets segment {id} at depth {depth}, behind the closest so far."};
constexpr Saying miss{"forms.miss", "Image space, pixel {pixel}: the projector misses segment {id}."};
constexpr Saying pixel{"forms.pixel", "Pixel {pixel} takes the colour of segment {id}, the closest primitive, at depth {depth}."};
constexpr Saying empty{"forms.empty", "Pixel {pixel}: no segment on its projector; it keeps the background."};
constexpr Saying done{"forms.done", "Done. Object space: {comparisons} comparisons, P·(P − 1) for P = {P}. Image space: {tests} tests, p·P for p = {p}. The two images differ in {differing} pixels."};
constexpr Saying bound{"forms.bound", "Stopped: the step bound was reached after {comparisons} comparisons and {tests} tests."};
constexpr Saying all[] = {shown, shown_ortho, projected, out_of_view, hides, behind, apart, visible, hidden, rendered, no_pixel,
                          closest, farther, miss, pixel, empty, done, bound};
}  // namespace say

// Intervals as "[a, b), [c, d)".
std::string intervals(const std::vector<glm::dvec2>& parts) {
    std::string s;
    for (const glm::dvec2 p : parts) s += (s.empty() ? "[" : ", [") + format_number(p.x) + ", " + format_number(p.y) + ")";
    return s;
}

// Pixel numbers with runs shortened: "2–5, 9".
std::string pixel_runs(const std::vector<std::uint32_t>& pixels) {
    std::string s;
    for (std::size_t k = 0; k < pixels.size();) {
        std::size_t end = k;
        while (end + 1 < pixels.size() && pixels[end + 1] == pixels[end] + 1) ++end;
        s += (s.empty() ? "" : ", ") + std::to_string(pixels[k]) + (end > k ? "–" + std::to_string(pixels[end]) : "");
        k = end + 1;
    }
    return s;
}

}  // namespace

std::span<const Saying> forms_sayings() { return say::all; }

Phrase phrase(const FormsEvent& event) {
    const auto n = [](auto v) { return std::to_string(v); };
    const auto f = [](double v) { return format_number(v); };
    return std::visit(
        overloaded{
            [&](const FormsShown& e) {
                return Phrase(e.perspective ? say::shown : say::shown_ortho, {{"primitives", n(e.primitives)}, {"pixels", n(e.pixels)}});
            },
            [&](const PrimitiveProjected& e) {
                if (!e.in_view) return Phrase(say::out_of_view, {{"id", n(e.id)}});
                return Phrase(say::projected, {{"id", n(e.id)}, {"from", f(e.from)}, {"to", f(e.to)}});
            },
            [&](const PrimitivesCompared& e) {
                if (e.hides) return Phrase(say::hides, {{"id", n(e.id)}, {"other", n(e.other_id)}, {"from", f(e.hidden_from)}, {"to", f(e.hidden_to)}});
                return Phrase(e.overlap ? say::behind : say::apart, {{"id", n(e.id)}, {"other", n(e.other_id)}});
            },
            [&](const VisiblePartFound& e) {
                if (e.parts.empty()) return Phrase(say::hidden, {{"id", n(e.id)}});
                return Phrase(say::visible, {{"id", n(e.id)}, {"parts", intervals(e.parts)}, {"percent", n(int(std::lround(100 * e.share)))}});
            },
            [&](const PartRendered& e) {
                if (e.pixels.empty()) return Phrase(say::no_pixel, {{"id", n(e.id)}});
                return Phrase(say::rendered, {{"id", n(e.id)}, {"pixels", pixel_runs(e.pixels)}});
            },
            [&](const ProjectorTested& e) {
                if (!e.hit) return Phrase(say::miss, {{"pixel", n(e.pixel)}, {"id", n(e.id)}});
                return Phrase(e.closest ? say::closest : say::farther, {{"pixel", n(e.pixel)}, {"id", n(e.id)}, {"depth", f(e.depth)}});
            },
            [&](const PixelRendered& e) {
                if (e.primitive < 0) return Phrase(say::empty, {{"pixel", n(e.pixel)}});
                return Phrase(say::pixel, {{"pixel", n(e.pixel)}, {"id", n(e.id)}, {"depth", f(e.depth)}});
            },
            [&](const FormsFinished& e) {
                if (e.bounded) return Phrase(say::bound, {{"comparisons", n(e.comparisons)}, {"tests", n(e.tests)}});
                return Phrase(say::done, {{"comparisons", n(e.comparisons)}, {"P", n(e.in_view)}, {"tests", n(e.tests)}, {"p", n(e.pixels)},
                                          {"differing", n(e.differing)}});
            },
        },
        event);
}

std::string describe(const FormsEvent& event) { return phrase(event).english(); }

}  // namespace hsr::algo
