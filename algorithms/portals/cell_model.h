// SPDX-License-Identifier: MIT
// Cells and portals, built from a scene's floor plan: each cell a convex room (its walls, with openings where its
// portals are, and its floor), each portal an opening in a wall two cells share, kept once for each way through.
// Plan coordinates (x, y) are the world's (x, −z); the floor is at world y = 0, the ceiling at the rooms' height
// (rooms have no ceiling polygon, so that a view from above can look in).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/plane.h"
#include "scene/scene.h"

namespace hsr::algo {

using Vec2 = glm::dvec2;

struct CellPolygon {
    SceneId id;
    Color color;
    std::uint32_t cell;
    std::vector<Vec3> vertices;  // world, counter-clockwise seen from inside the cell (its front faces the cell)
    Plane plane;
};

struct Portal {
    std::uint32_t from, to;      // going through it from cell `from` into cell `to`
    Vec2 left, right;            // its ends in the plan, as seen going through (left on the left)
    std::vector<Vec3> opening;   // world: the opening's outline (a rectangle, or the shape the plan gives), convex
    Plane plane;                 // of the opening; its front faces `to`
    std::uint32_t twin;          // the same opening the other way
};

struct Cell {
    std::string name;
    std::vector<Vec2> outline;            // plan, convex, counter-clockwise
    std::vector<std::uint32_t> portals;   // leading out of it
    std::vector<std::uint32_t> polygons;  // its walls, floor and objects
};

struct CellModel {
    std::vector<Cell> cells;
    std::vector<Portal> portals;
    std::vector<CellPolygon> polygons;
    double height = 3;
    Camera camera;      // the scene's, standing at the floor plan's eye when it gives one
    Tolerance tol;      // 1e-9 × the plan's extent
};

// Throws InvalidInput when the scene has no cells, or an object (a scene polygon) is in no cell.
CellModel cell_model(const Scene& scene);
// Every polygon of the model as a world-space scene with the model's camera (for the ray-cast reference).
Scene model_scene(const CellModel& model);

// The cell whose outline holds p (boundaries included), by testing every cell: the reference for the BSP.
std::optional<std::uint32_t> cell_at(const CellModel& model, Vec2 p);
bool inside(const std::vector<Vec2>& outline, Vec2 p, double eps);
// Whether a point of the opening's plane lies within its outline, at least `margin` inside (a negative margin lets
// points on the edge and just beyond count).
bool in_opening(const Portal& p, const Vec3& point, double margin);

inline Vec2 plan_point(const Vec3& world) { return {world.x, -world.z}; }
inline Vec3 world_point(Vec2 plan, double height) { return {plan.x, height, -plan.y}; }

}  // namespace hsr::algo
