// SPDX-License-Identifier: MIT
// Loading a scene from TOML. The format, by example (every field but the geometry is optional):
//
//   name = "Three segments"
//   description = "…"
//   coordinates = "world"            # or "clip": vertices are [x, y, z, w] in clip space, used as they are
//   [camera]
//   projection = "perspective"       # or "orthographic" with box = [left, right, bottom, top]
//   eye = [0, 0, 5]  target = [0, 0, 0]  up = [0, 1, 0]  fov = 60  aspect = 1  near = 1  far = 10
//   [[points]]    id = 1  color = "#e69f00"  p = [0, 0, 0]
//   [[segments]]  id = 2  color = "#56b4e9"  a = [-3, 0, 0]  b = [0.5, 0.2, -2]
//   [[polygons]]  id = 3  color = "#009e73"  vertices = [[…], […], […]]  opacity = 0.5   # opacity: 0 … 1, default 1
//   [[expect.clip]] id = 2  outcome = "clipped"  vertices = [[…, w], [… , w]]  max_error = 1e-15   # clip space
//   [[expect.image]] algorithm = "zbuffer"  format = "int16"  size = [64, 48]  max_differing = 0.01  visible = [3]
//   [[expect.rejects]] algorithm = "depth-sort"  message = "not convex"
//   promise = "…"                    # extreme cases (assets/scenes/extreme): the behaviour the expectations check
//   [floor_plan] …  [expect.pvs] …   # cells and portals: see scene/load_floor_plan.h
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"
#include "scene/toml_reader.h"

namespace hsr::algo {

Scene load_scene(const std::string& path);                          // throws LoadError
Scene load_scene_text(const std::string& path, std::string_view text);  // throws LoadError
Scene read_scene(const TomlReader& toml);
// Does a polygon (3 or more vertices) have area? Decided exactly: vertices on one line or at one point have none; a
// sliver of any area has some (geometry/exact_collinear.h).
bool has_area(const std::vector<glm::dvec4>& vertices);
// The sentence for what a reader left out: "city.obj: 3 faces of no area left out (face 2243 first)".
std::string left_out_of_no_area(const std::string& where, std::size_t count, const std::string& what, const std::string& first);
// How far the polygon's farthest vertex lies off its (Newell) plane, as a share of the polygon's size: 0 for a
// planar polygon, about 1e-16 for one given with rounding. A scene refuses more than max_bend.
double bend(const std::vector<glm::dvec4>& vertices);
inline constexpr double max_bend = 1e-4;
std::string not_planar(double bend);  // the message for a polygon bent more than max_bend
// World coordinates beyond this are refused: products of three coordinates (plane tests, Newell's normal) stay finite.
inline constexpr double max_world_coordinate = 1e100;

}  // namespace hsr::algo
