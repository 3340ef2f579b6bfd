// Meshes from OBJ files (tinyobjloader) placed in a scene:
//   [[meshes]]  file = "../meshes/torus.obj"  id = 100  color = "#cc79a7"  translate = [0, 1, 0]  scale = 2  turn = 30
// Each face becomes a polygon with ids counting up from `id`, scaled, turned about y (degrees) and moved; faces
// keep the file's winding (counter-clockwise seen from outside, for back-face culling).
#pragma once

#include "scene/scene.h"
#include "scene/toml_reader.h"

namespace hsr::algo {

// Appends the polygons of every [[meshes]] entry to the scene (paths relative to the scene file).
void read_meshes(const TomlReader& r, Scene& scene);

}  // namespace hsr::algo
