// SPDX-License-Identifier: MIT
// What the general forms of hidden-surface elimination tell (the Greek notes' introduction): the object-space form
// comparing each primitive against every other to find its visible part, then the image-space form finding the
// closest primitive through every pixel. The world is a floor plan (flatland): primitives are segments, the image is
// one row of pixels, so every visible part is a set of intervals a student can see whole.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <glm/vec2.hpp>

#include "core/phrase.h"

namespace hsr::algo {

struct FormsShown {
    static constexpr std::string_view kind = "FormsShown";
    std::uint32_t primitives, pixels;
    bool perspective;
    bool operator==(const FormsShown&) const = default;
};
// A primitive seen by the camera: its part between the near and far lines and inside the field of view, as an
// interval [from, to) of the image line u (−1 at the image's left edge, +1 at its right). Not in view: nothing of it
// is left (outside, behind the eye, edge-on, or with coordinates too large for doubles).
struct PrimitiveProjected {
    static constexpr std::string_view kind = "PrimitiveProjected";
    std::uint32_t primitive;
    std::int32_t id;  // the scene's
    bool in_view;
    double from, to;
    bool operator==(const PrimitiveProjected&) const = default;
};
// Object space: `primitive` compared against `other`. Where their images overlap, the other hides the part of
// [hidden_from, hidden_to) where it is nearer (one interval: along a line, 1/z is linear in u, so two primitives
// swap order at most once).
struct PrimitivesCompared {
    static constexpr std::string_view kind = "PrimitivesCompared";
    std::uint32_t primitive, other;
    std::int32_t id, other_id;
    bool overlap, hides;
    double hidden_from, hidden_to;
    bool operator==(const PrimitivesCompared&) const = default;
};
// Object space: what is left of a primitive's image after every comparison, as intervals of u in order.
struct VisiblePartFound {
    static constexpr std::string_view kind = "VisiblePartFound";
    std::uint32_t primitive;
    std::int32_t id;
    std::vector<glm::dvec2> parts;  // (from, to)
    double share;                   // of its image that is visible, 0 … 1
    bool operator==(const VisiblePartFound&) const = default;
};
// Object space: the visible part drawn, each pixel whose centre lies in it.
struct PartRendered {
    static constexpr std::string_view kind = "PartRendered";
    std::uint32_t primitive;
    std::int32_t id;
    std::vector<std::uint32_t> pixels;
    bool operator==(const PartRendered&) const = default;
};
// Image space: the projector through a pixel's centre tested against one primitive.
struct ProjectorTested {
    static constexpr std::string_view kind = "ProjectorTested";
    std::uint32_t pixel, primitive;
    std::int32_t id;
    bool hit;
    double depth;       // along the view direction, where it hits
    bool closest;       // the closest hit so far
    bool operator==(const ProjectorTested&) const = default;
};
// Image space: the pixel drawn with the colour of the closest primitive (id −1: none, the background).
struct PixelRendered {
    static constexpr std::string_view kind = "PixelRendered";
    std::uint32_t pixel;
    std::int32_t primitive, id;
    double depth;
    bool operator==(const PixelRendered&) const = default;
};
struct FormsFinished {
    static constexpr std::string_view kind = "FormsFinished";
    std::uint32_t primitives, in_view, pixels;
    std::uint64_t comparisons;  // object space: every primitive in view against every other, P·(P − 1)
    std::uint64_t tests;        // image space: every pixel against every primitive in view, p·P
    std::uint32_t differing;    // pixels the two forms drew differently
    bool bounded;               // stopped at the step bound
    bool operator==(const FormsFinished&) const = default;
};

using FormsEvent = std::variant<FormsShown, PrimitiveProjected, PrimitivesCompared, VisiblePartFound, PartRendered,
                                ProjectorTested, PixelRendered, FormsFinished>;

Phrase phrase(const FormsEvent& e);
std::string describe(const FormsEvent& e);
std::span<const Saying> forms_sayings();

}  // namespace hsr::algo
