// SPDX-License-Identifier: MIT
#include "scene/generated_scenes.h"

#include <cmath>
#include <cstdlib>

#include "core/numeric.h"
#include "core/portable_random.h"

namespace hsr::algo {
namespace {

void add_triangle(Scene& s, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, Color color, SceneId& id) {
    s.polygons.push_back({id++, color, {glm::dvec4(a, 1), glm::dvec4(b, 1), glm::dvec4(c, 1)}});
}
// A quad a b c d, counter-clockwise seen from its front, as two triangles.
void add_quad(Scene& s, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d, Color color, SceneId& id) {
    add_triangle(s, a, b, c, color, id);
    add_triangle(s, a, c, d, color, id);
}

Color random_color(PortableRandom& rng) {
    const auto channel = [&] { return std::uint8_t(rng.integer(70, 240)); };
    return {channel(), channel(), channel()};  // (a braced list: evaluated left to right)
}

}  // namespace

void add_box(Scene& s, glm::dvec3 l, glm::dvec3 h, Color color, SceneId& id) {
    const auto c = [&](int k) { return glm::dvec3(k & 1 ? h.x : l.x, k & 2 ? h.y : l.y, k & 4 ? h.z : l.z); };
    add_quad(s, c(0), c(4), c(6), c(2), color, id);  // −x
    add_quad(s, c(1), c(3), c(7), c(5), color, id);  // +x
    add_quad(s, c(0), c(1), c(5), c(4), color, id);  // −y
    add_quad(s, c(2), c(6), c(7), c(3), color, id);  // +y
    add_quad(s, c(0), c(2), c(3), c(1), color, id);  // −z
    add_quad(s, c(4), c(5), c(7), c(6), color, id);  // +z
}

void add_turned_box(Scene& s, glm::dvec3 centre, glm::dvec3 half, const glm::dmat3& turn, Color color, SceneId& id) {
    const auto c = [&](int k) { return centre + turn * glm::dvec3(k & 1 ? half.x : -half.x, k & 2 ? half.y : -half.y, k & 4 ? half.z : -half.z); };
    add_quad(s, c(0), c(4), c(6), c(2), color, id);  // the same faces as add_box: a rotation keeps them outward
    add_quad(s, c(1), c(3), c(7), c(5), color, id);
    add_quad(s, c(0), c(1), c(5), c(4), color, id);
    add_quad(s, c(2), c(6), c(7), c(3), color, id);
    add_quad(s, c(0), c(2), c(3), c(1), color, id);
    add_quad(s, c(4), c(5), c(7), c(6), color, id);
}

void add_sphere(Scene& s, glm::dvec3 centre, double r, int slices, int stacks, Color color, SceneId& id) {
    const auto at = [&](int i, int j) {
        const double theta = 2 * M_PI * i / slices, phi = M_PI * j / stacks;
        return centre + r * glm::dvec3(std::sin(phi) * std::cos(theta), std::cos(phi), -std::sin(phi) * std::sin(theta));
    };
    for (int j = 0; j < stacks; ++j)
        for (int i = 0; i < slices; ++i) {
            const glm::dvec3 a = at(i, j), b = at(i, j + 1), c = at(i + 1, j + 1), d = at(i + 1, j);
            if (j == 0) add_triangle(s, a, b, c, color, id);              // the cap: a and d are the pole
            else if (j == stacks - 1) add_triangle(s, a, b, d, color, id);  // b and c are the other pole
            else add_quad(s, a, b, c, d, color, id);
        }
}

std::optional<std::size_t> generated_triangles(const std::string& name) {
    const std::size_t colon = name.find(':');
    const std::string kind = name.substr(0, colon);
    if (colon == std::string::npos || (kind != "city" && kind != "field" && kind != "spheres")) return std::nullopt;
    const std::string count = name.substr(colon + 1);
    char* end = nullptr;
    const unsigned long long n = std::strtoull(count.c_str(), &end, 10);
    if (count.empty() || count.find_first_not_of("0123456789") != std::string::npos || *end != 0 || n < 12 || n > 20'000'000)
        throw InvalidInput(name + ": expected " + kind + ":N with N from 12 to 20000000 triangles");
    return std::size_t(n);
}

std::optional<Scene> generated_scene(const std::string& name) {
    const auto n = generated_triangles(name);
    if (!n) return std::nullopt;
    const GeneratedScene g{.triangles = *n};
    const std::string kind = name.substr(0, name.find(':'));
    return kind == "city" ? city_scene(g) : kind == "field" ? field_scene(g) : spheres_scene(g);
}

Scene city_scene(GeneratedScene o) {
    Scene s;
    s.name = "city of blocks";
    s.source = "city_scene(" + std::to_string(o.triangles) + " triangles, seed " + std::to_string(o.seed) + ")";
    PortableRandom rng(o.seed);
    const auto blocks = std::size_t(std::ceil(std::sqrt(double(o.triangles) / 12)));  // 12 triangles a building
    const double lot = 10, street = 6;
    SceneId id = 1;
    // Buildings on a square grid of lots; the camera stands in the middle of the first street, looking along it
    for (std::size_t i = 0; i < blocks; ++i)
        for (std::size_t j = 0; j < blocks; ++j) {
            const double x = double(i) * (lot + street) + street, z = -double(j) * (lot + street) - street;
            const double left = rng.uniform(0, 1.2), back = rng.uniform(0, 1.2), right = rng.uniform(0, 1.2);
            const double height = rng.uniform(3, 18), front = rng.uniform(0, 1.2);
            const Color color = random_color(rng);
            add_box(s, {x + left, 0, z - lot + back}, {x + lot - right, height, z - front}, color, id);
        }
    const double along = double(blocks) * (lot + street);
    add_quad(s, {0, 0, 0}, {along + street, 0, 0}, {along + street, 0, -along - street}, {0, 0, -along - street}, {90, 92, 98}, id);  // the ground
    // in the street between the first two rows of blocks, looking along it
    const double x = blocks > 1 ? lot + street + street / 2 : street / 2;
    s.camera = {.eye = {x, 1.7, -2}, .target = {x + 1.5, 2.5, -along}, .fov_y = 60, .aspect = 4.0 / 3, .near = 0.5, .far = 2 * along + 10};
    return s;
}

Scene field_scene(GeneratedScene o) {
    Scene s;
    s.name = "field of objects";
    s.source = "field_scene(" + std::to_string(o.triangles) + " triangles, seed " + std::to_string(o.seed) + ")";
    PortableRandom rng(o.seed);
    const std::size_t objects = std::max<std::size_t>(1, o.triangles / 12);
    const double radius = 8 * std::cbrt(double(objects));  // the same density at any size
    const auto u = [&] { return rng.uniform(-1, 1); };
    SceneId id = 1;
    for (std::size_t k = 0; k < objects; ++k) {
        glm::dvec3 c;
        do c = {u(), u(), u()};
        while (glm::dot(c, c) > 1 || glm::dot(c, c) < 0.0004);
        c *= radius;
        const double h = rng.uniform(0.2, 1.0) / 2;
        const Color color = random_color(rng);
        add_box(s, c - glm::dvec3(h), c + glm::dvec3(h), color, id);
    }
    s.camera = {.eye = {0, 0, 0}, .target = {0, 0, -1}, .fov_y = 60, .aspect = 4.0 / 3, .near = 0.1, .far = 2 * radius};
    return s;
}

Scene spheres_scene(GeneratedScene o) {
    Scene s;
    s.name = "closed spheres";
    s.source = "spheres_scene(" + std::to_string(o.triangles) + " triangles, seed " + std::to_string(o.seed) + ")";
    PortableRandom rng(o.seed);
    const int slices = 16, stacks = 8;  // 16 × 6 quads + 2 × 16 cap triangles = 224 triangles a sphere
    const std::size_t count = std::max<std::size_t>(1, o.triangles / 224);
    const auto side = std::size_t(std::ceil(std::sqrt(double(count))));
    SceneId id = 1;
    for (std::size_t k = 0; k < count; ++k) {
        const double x = (double(k % side) - double(side - 1) / 2) * 3, y = (double(k / side) - double(side - 1) / 2) * 3;
        const glm::dvec3 centre{x + rng.uniform(-0.5, 0.5), y + rng.uniform(-0.5, 0.5), -rng.uniform(-0.5, 0.5) * 2};
        const Color color = random_color(rng);
        add_sphere(s, centre, 1.2, slices, stacks, color, id);
    }
    const double back = 3.0 * double(side) + 4;
    s.camera = {.eye = {0, 0, back}, .target = {0, 0, 0}, .fov_y = 60, .aspect = 4.0 / 3, .near = 0.5, .far = 3 * back};
    return s;
}

}  // namespace hsr::algo
