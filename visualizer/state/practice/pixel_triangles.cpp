// SPDX-License-Identifier: MIT
#include "state/practice/pixel_triangles.h"

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "geometry/polygon_2d.h"
#include "core/okabe_ito.h"

namespace hsr::viz::practice {
namespace {

using glm::dvec2;
constexpr double eye_z = 10;  // the camera's; a triangle at world z is at distance 10 − z

// Which side of the edge a → b the point p is on: orientation(a, b, p), twice the signed area of (a, b, p) in pixels².
using algo::orientation;

}  // namespace

std::optional<std::vector<PixelTriangle>> draw_pixel_triangles(Dice& d, Level l) {
    const int count = l == Level::easy ? 2 : 3;
    std::vector<double> depths = {2, 3, 4, 5, 6, 7, 8, 9};
    for (std::size_t i = depths.size(); i > 1; --i) std::swap(depths[i - 1], depths[std::size_t(d.below(int(i)))]);
    std::vector<PixelTriangle> t;
    for (int k = 0; k < count; ++k) {
        PixelTriangle tri{};
        for (dvec2& c : tri.corner) c = {d.grid(1, pixel_grid.width - 1, 1), d.grid(1, pixel_grid.height - 1, 1)};
        if (std::abs(orientation(tri.corner[0], tri.corner[1], tri.corner[2])) < 40) return std::nullopt;  // at least 20 px²
        tri.depth = depths[std::size_t(k)];
        t.push_back(tri);
    }
    if (l == Level::hard) t[1].depth = t[0].depth + (d.coin() ? 0.05 : -0.05);
    return t;
}

algo::Scene pixel_grid_scene(std::string name) {
    algo::Scene scene;
    scene.name = std::move(name);
    scene.camera.projection = algo::Projection::orthographic;
    scene.camera.eye = {0, 0, eye_z};
    scene.camera.target = {0, 0, 0};
    scene.camera.near = 1;
    scene.camera.far = eye_z;
    // eye space x = pixel x, eye space y = −pixel y: the box is the grid
    scene.camera.box[0] = 0, scene.camera.box[1] = pixel_grid.width, scene.camera.box[2] = -pixel_grid.height, scene.camera.box[3] = 0;
    return scene;
}

glm::dvec4 pixel_point(dvec2 at, double depth) { return {at.x, -at.y, eye_z - depth, 1}; }

algo::Scene pixel_triangle_scene(const std::vector<PixelTriangle>& triangles) {
    static const algo::Color colours[] = {algo::okabe_ito::as<algo::Color>(algo::okabe_ito::orange), algo::okabe_ito::as<algo::Color>(algo::okabe_ito::sky_blue), algo::okabe_ito::as<algo::Color>(algo::okabe_ito::bluish_green)};
    algo::Scene scene = pixel_grid_scene("triangles on fat pixels");
    for (std::size_t k = 0; k < triangles.size(); ++k) {
        algo::ScenePolygon p{algo::SceneId(k + 1), colours[k % 3], {}};
        for (const dvec2& c : triangles[k].corner) p.vertices.push_back(pixel_point(c, triangles[k].depth));
        scene.polygons.push_back(p);
    }
    return scene;
}

bool covers(const PixelTriangle& t, dvec2 p) {
    const double e0 = orientation(t.corner[0], t.corner[1], p), e1 = orientation(t.corner[1], t.corner[2], p),
                 e2 = orientation(t.corner[2], t.corner[0], p);
    return (e0 > 0 && e1 > 0 && e2 > 0) || (e0 < 0 && e1 < 0 && e2 < 0);
}

bool near_an_edge(const PixelTriangle& t, dvec2 p) {
    for (int k = 0; k < 3; ++k) {
        const dvec2 a = t.corner[k], b = t.corner[(k + 1) % 3];
        if (std::abs(orientation(a, b, p)) / glm::length(b - a) < 0.1) return true;
    }
    return false;
}

std::vector<std::pair<int, int>> pixels_covered(const std::vector<PixelTriangle>& t, int at_least) {
    std::vector<std::pair<int, int>> at;
    for (int y = 0; y < pixel_grid.height; ++y)
        for (int x = 0; x < pixel_grid.width; ++x) {
            const dvec2 centre(x + 0.5, y + 0.5);
            int inside = 0;
            bool clear = true;
            for (const PixelTriangle& k : t) {
                inside += covers(k, centre);
                clear = clear && !near_an_edge(k, centre);
            }
            if (inside >= at_least && clear) at.emplace_back(x, y);
        }
    return at;
}

std::optional<std::pair<int, int>> pick_pixel(Dice& d, const std::vector<PixelTriangle>& t, int at_least) {
    const auto pixels = pixels_covered(t, at_least);
    if (pixels.empty()) return std::nullopt;
    return pixels[std::size_t(d.below(int(pixels.size())))];
}

namespace say {
using algo::Saying;
constexpr Saying first{"pixel_triangles.first", "triangle {number} ({corners}, depth {depth})"};
constexpr Saying then{"pixel_triangles.then", "then triangle {number} ({corners}, depth {depth})"};
constexpr Saying grid{"pixel_triangles.grid",
                      "{triangles}, on a 32 × 24 grid: corners in pixels, x to the right and y down, pixel (i, j) the square "
                      "from (i, j) to (i + 1, j + 1), taken at its centre; depth is the distance from the eye, and the nearer "
                      "wins. (The machine numbers them from 0: triangle 1 is its #0.)"};
constexpr Saying triangle{"pixel_triangles.triangle", "triangle {number}"};
constexpr Saying background{"pixel_triangles.background", "none: the background"};
constexpr Saying all[] = {first, then, grid, triangle, background};
}  // namespace say

Wording pixel_triangles_text(const std::vector<PixelTriangle>& t) {
    std::vector<Wording> drawn;
    for (std::size_t k = 0; k < t.size(); ++k) {
        std::string corners;
        for (int c = 0; c < 3; ++c)
            corners += (c ? ", " : "") + std::string("(") + number_text(t[k].corner[c].x) + ", " + number_text(t[k].corner[c].y) + ")";
        drawn.push_back(Wording(k == 0 ? say::first : say::then,
                                {{"number", std::to_string(k + 1)}, {"corners", corners}, {"depth", number_text(t[k].depth)}}));
    }
    return Wording(say::grid, {}, {{"triangles", drawn}});
}

std::vector<Wording> triangle_choices(std::size_t triangles) {
    std::vector<Wording> choices;
    for (std::size_t k = 0; k < triangles; ++k) choices.push_back(Wording(say::triangle, {{"number", std::to_string(k + 1)}}));
    choices.push_back(Wording(say::background));
    return choices;
}

std::span<const algo::Saying> pixel_triangle_sayings() { return say::all; }

nlohmann::json pixel_triangles_given(const std::vector<PixelTriangle>& t, const char* kind, int x, int y, std::size_t triangle) {
    nlohmann::json tri = nlohmann::json::array();
    for (const PixelTriangle& k : t)
        tri.push_back({{"corners", {{k.corner[0].x, k.corner[0].y}, {k.corner[1].x, k.corner[1].y}, {k.corner[2].x, k.corner[2].y}}},
                       {"depth", k.depth}});
    return {{"kind", kind}, {"triangles", tri}, {"pixel", {x, y}}, {"triangle", triangle}};
}

}  // namespace hsr::viz::practice
