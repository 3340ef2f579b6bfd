// SPDX-License-Identifier: MIT
// Wide lines as triangles (render/wide_lines.h): the width in pixels, square caps, the near plane clipped in clip
// space (an end behind the eye never divides by w ≤ 0), nothing for a segment wholly behind.
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "catch.h"
#include "render/wide_lines.h"

using namespace hsr::viz;

namespace {
const glm::vec4 red{1, 0, 0, 1};
std::vector<ColoredVertex> segment(glm::vec3 a, glm::vec3 b) { return {{a, red}, {b, red}}; }
// a corner's place in pixels of a W × H viewport
glm::vec2 pixels(const ColoredVertex& v, glm::vec2 viewport) { return (glm::vec2(v.position) * 0.5f + 0.5f) * viewport; }
}  // namespace

TEST_CASE("a wide line is a rectangle its width in pixels across, with square caps", "[render][wide-lines]") {
    const glm::vec2 viewport(800, 600);
    std::vector<ColoredVertex> out;
    // identity: world = normalised device coordinates; from pixel (200, 300) to (600, 300)
    wide_line_triangles(segment({-0.5f, 0, 0.25f}, {0.5f, 0, 0.25f}), glm::mat4(1), 6.0f, viewport, out);
    REQUIRE(out.size() == 6);
    float x_min = 1e9f, x_max = -1e9f, y_min = 1e9f, y_max = -1e9f;
    for (const ColoredVertex& v : out) {
        const glm::vec2 p = pixels(v, viewport);
        x_min = std::min(x_min, p.x), x_max = std::max(x_max, p.x), y_min = std::min(y_min, p.y), y_max = std::max(y_max, p.y);
        CHECK(v.position.z == Approx(0.25f));  // depth kept for the depth test
        CHECK(v.color == red);
    }
    CHECK(y_max - y_min == Approx(6.0f).margin(1e-3));   // 6 pixels across
    CHECK(x_min == Approx(200 - 3.0f).margin(1e-3));     // and half the width beyond each end
    CHECK(x_max == Approx(600 + 3.0f).margin(1e-3));
    // two triangles of the same winding covering the rectangle: their areas add up to its area
    const auto area = [&](std::size_t k) {
        const glm::vec2 a = pixels(out[k], viewport), b = pixels(out[k + 1], viewport), c = pixels(out[k + 2], viewport);
        return 0.5f * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
    };
    CHECK(std::abs(area(0)) + std::abs(area(3)) == Approx(406.0f * 6.0f).epsilon(1e-4));
    CHECK(area(0) * area(3) > 0);

    // a diagonal line keeps its width across (not its width in x)
    out.clear();
    wide_line_triangles(segment({-0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}), glm::ortho(-1.f, 1.f, -1.f, 1.f, -1.f, 1.f), 4.0f, {600, 600}, out);
    REQUIRE(out.size() == 6);
    CHECK(glm::distance(pixels(out[0], {600, 600}), pixels(out[1], {600, 600})) == Approx(4.0f).margin(1e-3));

    // a point-like segment: a square of the width; a zero-sized viewport: nothing
    out.clear();
    wide_line_triangles(segment({0, 0, 0}, {0, 0, 0}), glm::mat4(1), 5.0f, viewport, out);
    REQUIRE(out.size() == 6);
    CHECK(glm::distance(pixels(out[0], viewport), pixels(out[5], viewport)) == Approx(5.0f * std::sqrt(2.0f)).margin(1e-3));
    out.clear();
    wide_line_triangles(segment({0, 0, 0}, {1, 0, 0}), glm::mat4(1), 5.0f, {0, 600}, out);
    CHECK(out.empty());
}

TEST_CASE("a wide line crossing the eye's plane is clipped at the near plane, never divided by w ≤ 0", "[render][wide-lines]") {
    const glm::mat4 vp = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f) *
                         glm::lookAt(glm::vec3(0, 0, 0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
    std::vector<ColoredVertex> out;
    // from 5 in front of the eye to 5 behind it, and one end exactly at the eye (w = 0)
    for (const glm::vec3 behind : {glm::vec3(1, 0, 5), glm::vec3(0, 0, 0), glm::vec3(0.3f, 0.2f, 0.05f)}) {
        out.clear();
        wide_line_triangles(segment({1, 0, -5}, behind), vp, 3.0f, {800, 800}, out);
        REQUIRE(out.size() == 6);
        for (const ColoredVertex& v : out) {
            INFO(v.position.x << " " << v.position.y << " " << v.position.z);
            CHECK(std::isfinite(v.position.x));
            CHECK(std::isfinite(v.position.y));
            CHECK(v.position.z >= -1.0f - 1e-4f);  // on or beyond the near plane
            CHECK(v.position.z <= 1.0f);
        }
    }
    // wholly behind the eye, or not a number: nothing
    out.clear();
    wide_line_triangles(segment({1, 0, 5}, {-1, 0, 3}), vp, 3.0f, {800, 800}, out);
    wide_line_triangles(segment({std::numeric_limits<float>::quiet_NaN(), 0, -5}, {1, 0, -5}), vp, 3.0f, {800, 800}, out);
    CHECK(out.empty());
}
