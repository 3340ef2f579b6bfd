// SPDX-License-Identifier: MIT
// Generated scenes for the culling pipeline, reproducible from a seed, at any size: closed meshes wound outwards
// (counter-clockwise seen from outside), as triangles.
//   city:    blocks of buildings along streets, seen from the street: most of it is hidden behind the nearest
//            buildings (occlusion matters)
//   field:   small closed objects all round the camera, near and far: most are behind or beside it (the frustum
//            matters) or a few pixels across (detail matters)
//   spheres: closed spheres in front of the camera: half of every sphere faces away (back-face culling matters)
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <glm/mat3x3.hpp>

#include "scene/scene.h"

namespace hsr::algo {

struct GeneratedScene {
    std::size_t triangles = 1000;  // about this many
    std::uint32_t seed = 1;
};

Scene city_scene(GeneratedScene options);
Scene field_scene(GeneratedScene options);
Scene spheres_scene(GeneratedScene options);

// "city:N", "field:N" or "spheres:N" (about N triangles, seed 1) → the generated scene; nullopt for any other name.
// InvalidInput when the kind is one of those but N is not a count from 12 to 20,000,000.
std::optional<Scene> generated_scene(const std::string& name);
// The N of such a name (nothing generated yet: what a memory estimate needs first); nullopt and InvalidInput as above.
std::optional<std::size_t> generated_triangles(const std::string& name);

// A box from lo to hi as 12 triangles wound outwards; ids from `first_id`.
void add_box(Scene& scene, glm::dvec3 lo, glm::dvec3 hi, Color color, SceneId& next_id);
// A box with half-extents `half` about `centre`, turned by the rotation `turn`, as 12 triangles wound outwards.
void add_turned_box(Scene& scene, glm::dvec3 centre, glm::dvec3 half, const glm::dmat3& turn, Color color, SceneId& next_id);
// A UV sphere (slices × stacks quads, as triangles) wound outwards.
void add_sphere(Scene& scene, glm::dvec3 centre, double radius, int slices, int stacks, Color color, SceneId& next_id);

}  // namespace hsr::algo
