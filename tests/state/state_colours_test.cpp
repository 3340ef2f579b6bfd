// SPDX-License-Identifier: MIT
// The colours that carry a state stay apart for every student: each pair of a view's table differs by at least
// 15 ΔE (CIE 1976 L*a*b*) for normal vision and under Machado, Oliveira and Fernandes' (2009) simulation of
// protanopia, deuteranopia and tritanopia (severity 1).
#include <cmath>
#include <span>
#include <string>

#include "catch.h"
#include "state/state_colours.h"

using namespace hsr::viz;

namespace {

using Matrix = std::array<std::array<double, 3>, 3>;
struct Vision {
    const char* name;
    Matrix m;  // on linear RGB
};
constexpr Vision visions[] = {
    {"normal", {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}},
    {"protanopia", {{{0.152286, 1.052583, -0.204868}, {0.114503, 0.786281, 0.099216}, {-0.003882, -0.048116, 1.051998}}}},
    {"deuteranopia", {{{0.367322, 0.860646, -0.227968}, {0.280085, 0.672501, 0.047413}, {-0.011820, 0.042940, 0.968881}}}},
    {"tritanopia", {{{1.255528, -0.076749, -0.178779}, {-0.078411, 0.930809, 0.147602}, {0.004733, 0.691367, 0.303900}}}},
};

double linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// sRGB → simulated linear RGB → CIE XYZ (D65) → L*a*b*
std::array<double, 3> lab_seen(const StateColour& c, const Matrix& m) {
    const double in[3] = {linear(c.r), linear(c.g), linear(c.b)};
    double rgb[3];
    for (int i = 0; i < 3; ++i) rgb[i] = std::clamp(m[i][0] * in[0] + m[i][1] * in[1] + m[i][2] * in[2], 0.0, 1.0);
    const double x = (0.4124 * rgb[0] + 0.3576 * rgb[1] + 0.1805 * rgb[2]) / 0.95047;
    const double y = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
    const double z = (0.0193 * rgb[0] + 0.1192 * rgb[1] + 0.9505 * rgb[2]) / 1.08883;
    const auto f = [](double t) { return t > 216.0 / 24389 ? std::cbrt(t) : (24389.0 / 27 * t + 16) / 116; };
    return {116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))};
}

double delta_e(const StateColour& a, const StateColour& b, const Matrix& m) {
    const auto p = lab_seen(a, m), q = lab_seen(b, m);
    return std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
}

void every_pair_apart(std::span<const StateColour> table, double at_least) {
    for (const Vision& v : visions)
        for (std::size_t i = 0; i < table.size(); ++i)
            for (std::size_t j = i + 1; j < table.size(); ++j) {
                INFO(v.name << ": " << table[i].legend << " against " << table[j].legend);
                CHECK(delta_e(table[i], table[j], v.m) >= at_least);
            }
}

}  // namespace

TEST_CASE("the simulation is Machado's: white stays white, and red and green meet for a deuteranope", "[colours]") {
    const StateColour white{"", 1, 1, 1}, red{"", 0.8f, 0.2f, 0.1f}, green{"", 0.45f, 0.45f, 0.1f};
    for (const Vision& v : visions) CHECK(lab_seen(white, v.m)[0] == Approx(100).margin(0.5));
    // a red and an olive that normal vision tells apart well and a deuteranope hardly at all: the test can fail
    CHECK(delta_e(red, green, visions[0].m) > 30);
    CHECK(delta_e(red, green, visions[2].m) < delta_e(red, green, visions[0].m) / 2);
}

TEST_CASE("the culling boxes' states are told apart under every colour blindness", "[colours]") {
    every_pair_apart(culling_colours::all, 15);
}

TEST_CASE("the portal plan's cells (the one being drawn, visited, in the PVS, out of it) are told apart under every colour blindness", "[colours]") {
    every_pair_apart(portal_cell_colours::all, 15);
}

TEST_CASE("the perspective transform's marks (the pair compared, an occluding pair, the canonical box) are told apart under every colour blindness", "[colours]") {
    every_pair_apart(transform_colours::all, 15);
}

TEST_CASE("an occluder's orange stays apart from the marks an occlusion lesson shows beside it", "[colours]") {
    const std::array occlusion_lesson{culling_colours::partial, culling_colours::occluded, culling_colours::visible,
                                      culling_colours::built, culling_colours::occluder, culling_colours::frustum};
    every_pair_apart(occlusion_lesson, 15);
}

TEST_CASE("IntersectionTest's volumes (at work, met, missed, a false alarm) are told apart under every colour blindness", "[colours]") {
    every_pair_apart(intersection_colours::all, 15);
}

TEST_CASE("back-face culling's marks (under test, culled, culled though seen) are told apart under every colour blindness", "[colours]") {
    every_pair_apart(backface_colours::all, 15);
}

TEST_CASE("z-merge's frames (the nearer part, the farther) are told apart under every colour blindness", "[colours]") {
    every_pair_apart(zmerge_colours::all, 15);
}
