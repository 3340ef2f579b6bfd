// SPDX-License-Identifier: MIT
// The scene of the z-buffer's and the ray cast's exercises: fat pixels a student can count, and triangles given in
// pixel coordinates, each at one depth, seen head-on by an orthographic camera whose box is the 32 × 24 grid (a
// lesson's grid when it names none), so that pixel (i, j) of the machines is the square from (i, j) to (i + 1, j + 1).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "raster/screen_polygon.h"
#include "scene/scene.h"
#include "state/practice/practice.h"
#include "state/practice/practice_random.h"

namespace hsr::viz::practice {

inline constexpr algo::Viewport pixel_grid{32, 24};

struct PixelTriangle {
    glm::dvec2 corner[3];  // pixel coordinates: x right, y down
    double depth;          // the distance from the eye
};

// Two (easy) or three triangles with corners on whole pixels, at whole depths 2 … 9 (hard: two a twentieth apart,
// never equal), none thinner than 20 pixels²; nothing when the dice drew a thin one.
std::optional<std::vector<PixelTriangle>> draw_pixel_triangles(Dice& d, Level l);
algo::Scene pixel_triangle_scene(const std::vector<PixelTriangle>& triangles);

// The grid's scene with no polygons yet (an orthographic camera whose box is the grid, near 1, far 10), and the
// homogeneous world point of a pixel position at a depth in [1, 10]: for exercises whose polygons are not at one depth.
algo::Scene pixel_grid_scene(std::string name);
glm::dvec4 pixel_point(glm::dvec2 at, double depth);

// Is the point inside the triangle (strictly)? Is it a hair (a tenth of a pixel) from an edge's line?
bool covers(const PixelTriangle& t, glm::dvec2 p);
bool near_an_edge(const PixelTriangle& t, glm::dvec2 p);
// Pixels whose centre lies inside at least `at_least` triangles and a hair from no edge.
std::vector<std::pair<int, int>> pixels_covered(const std::vector<PixelTriangle>& t, int at_least);

// One of those pixels, by the dice; nothing when there is none.
std::optional<std::pair<int, int>> pick_pixel(Dice& d, const std::vector<PixelTriangle>& t, int at_least);

// "triangle 1 ((20, 15), (2, 9), (27, 14), depth 5); then triangle 2 (…)", and what the grid's numbers mean.
Wording pixel_triangles_text(const std::vector<PixelTriangle>& t);
// "triangle 1" … "triangle n", then "none: the background": the choices of a question about what a pixel shows.
std::vector<Wording> triangle_choices(std::size_t triangles);
// The templates of those (the catalogues' [exercise.pixel_triangles]).
std::span<const algo::Saying> pixel_triangle_sayings();
nlohmann::json pixel_triangles_given(const std::vector<PixelTriangle>& t, const char* kind, int x, int y, std::size_t triangle);

}  // namespace hsr::viz::practice
