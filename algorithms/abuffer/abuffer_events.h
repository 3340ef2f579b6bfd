// SPDX-License-Identifier: MIT
// What the A-buffer tells: each polygon scanned into fragments (a pixel it touches, with the coverage mask of the
// sub-samples it covers and its depth there), then each pixel's fragment list resolved front to back, sub-sample by
// sub-sample, into one antialiased, composited colour.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "core/phrase.h"

namespace hsr::algo {

struct ABufferStarted {
    static constexpr std::string_view kind = "ABufferStarted";
    std::int32_t width, height, mask_size;  // the mask is mask_size × mask_size bits per pixel
    std::uint32_t polygons;
    bool operator==(const ABufferStarted&) const = default;
};
// A polygon reaches a pixel: its fragment, with bit j·m + i of the mask set when the sub-sample at
// (x + (i + ½)/m, y + (j + ½)/m) is inside it (the z-buffer's fill rule), and its depth at those sub-samples' centre.
struct FragmentMade {
    static constexpr std::string_view kind = "FragmentMade";
    std::uint32_t polygon;
    std::int32_t x, y;
    std::uint64_t mask;
    std::uint32_t covered;  // bits set
    std::uint32_t samples;  // sub-samples per pixel (m²)
    double depth;           // window depth, 0 (near) … 1 (far)
    bool operator==(const FragmentMade&) const = default;
};
struct PolygonScanned {
    static constexpr std::string_view kind = "PolygonScanned";
    std::uint32_t polygon;
    std::uint32_t fragments;  // 0: outside the view, or covering no sub-sample
    double opacity;
    bool operator==(const PolygonScanned&) const = default;
};
// One fragment of a pixel's list, in front-to-back order: `shown` of its covered sub-samples still let light
// through when it came (not hidden behind opaque fragments in front), and `weight` is its share of the pixel's
// colour (the light it adds, averaged over the pixel).
struct FragmentResolved {
    static constexpr std::string_view kind = "FragmentResolved";
    std::int32_t x, y;
    std::uint32_t polygon, order;  // order: 0 for the nearest
    std::uint32_t covered, shown;
    double weight;
    bool operator==(const FragmentResolved&) const = default;
};
// The pixel's colour, premultiplied (r, g, b ≤ a), over nothing: a is the share of the pixel covered, opacity
// included.
struct PixelResolved {
    static constexpr std::string_view kind = "PixelResolved";
    std::int32_t x, y;
    std::uint32_t fragments;
    double r, g, b, a;
    bool operator==(const PixelResolved&) const = default;
};
struct ABufferFinished {
    static constexpr std::string_view kind = "ABufferFinished";
    std::uint64_t fragments;
    std::uint32_t pixels;         // with at least one fragment
    std::uint32_t longest_list;
    bool bounded;                 // stopped at the step bound (max_fragments)
    bool operator==(const ABufferFinished&) const = default;
};

using ABufferEvent = std::variant<ABufferStarted, FragmentMade, PolygonScanned, FragmentResolved, PixelResolved, ABufferFinished>;

Phrase phrase(const ABufferEvent& e);
std::string describe(const ABufferEvent& e);
std::span<const Saying> abuffer_sayings();

}  // namespace hsr::algo
