// SPDX-License-Identifier: MIT
// The Okabe–Ito palette (Okabe and Ito, "Color Universal Design", 2008): eight colours that people with each common
// colour blindness still tell apart. Named once here; the scenes' and cells' colours, the practice exercises, the
// report's charts, the 3D view (render/palette.h) and the state marks (state/state_colours.h) map it.
#pragma once

#include <array>
#include <cstdint>

namespace hsr::algo::okabe_ito {

struct Rgb8 {
    std::uint8_t r, g, b;
};

inline constexpr Rgb8 orange{230, 159, 0};
inline constexpr Rgb8 sky_blue{86, 180, 233};
inline constexpr Rgb8 bluish_green{0, 158, 115};
inline constexpr Rgb8 yellow{240, 228, 66};
inline constexpr Rgb8 blue{0, 114, 178};
inline constexpr Rgb8 vermillion{213, 94, 0};
inline constexpr Rgb8 reddish_purple{204, 121, 167};
inline constexpr Rgb8 black{0, 0, 0};

// The seven colours for things told apart by colour alone (polygons, cells, a chart's methods), in the order the
// shipped scenes use them.
inline constexpr std::array<Rgb8, 7> series{orange, sky_blue, bluish_green, yellow, blue, vermillion, reddish_purple};

// A chart's methods, a colour each: the series with the thin-lined yellow and then black last (the window's dark
// panel takes the first six).
inline constexpr std::array<Rgb8, 8> chart{orange, sky_blue, bluish_green, vermillion, blue, reddish_purple, yellow, black};

// As another colour type with r, g, b members (algo::Color): `as<Color>(okabe_ito::orange)`.
template <class C>
constexpr C as(const Rgb8& c) {
    return C{c.r, c.g, c.b};
}
// A channel in [0, 1], for GL and ImGui.
constexpr float unit(std::uint8_t channel) { return float(channel) / 255.0f; }

}  // namespace hsr::algo::okabe_ito
