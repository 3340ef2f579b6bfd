// SPDX-License-Identifier: MIT
// Reading a scene's [floor_plan] (cells and portals) and its [expect.pvs], with the checks a teacher needs when
// writing one by hand: convex cells with unique names, portals on a wall the two cells share.
//
//   [floor_plan]  height = 3  eye = [1, 1]  look = [5, 1]  eye_height = 1.6
//   [[floor_plan.cells]]    name = "A"  rect = [0, 0, 2, 2]          # or outline = [[x, y], …] (convex)
//   [[floor_plan.portals]]  between = ["A", "B"]  from = [2, 0.5]  to = [2, 1.5]  top = 2.2   # top: optional
//   [expect.pvs]  A = ["A", "B"]  B = ["A", "B"]
#pragma once

#include "scene/scene.h"
#include "scene/toml_reader.h"

namespace hsr::algo {

FloorPlan read_floor_plan(const TomlReader& r, const toml::table* t);  // t may be null: no cells
std::vector<ExpectPvs> read_expect_pvs(const TomlReader& r, const toml::table* t, const FloorPlan& plan);

}  // namespace hsr::algo
