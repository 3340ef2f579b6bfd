// SPDX-License-Identifier: MIT
// Meshes from OBJ files (tinyobjloader) placed in a scene:
//   [[meshes]]  file = "meshes/torus.obj"  id = 100  color = "#cc79a7"  translate = [0, 1, 0]  scale = 2  turn = 30
// Each face becomes a polygon with ids counting up from `id`, scaled, turned about y (degrees) and moved; faces
// keep the file's winding (counter-clockwise seen from outside, for back-face culling).
#pragma once

#include "scene/scene.h"
#include "scene/toml_reader.h"

namespace hsr::algo {

// Appends the polygons of every [[meshes]] entry to the scene. A mesh's path is relative to the scene file, ends in
// .obj and stays inside the scene's folder (a scene handed around cannot read ../../etc/passwd) unless
// HSRVIZ_MESHES_ANYWHERE=1 is set. Every vertex coordinate must be a finite number and every face index must name
// a vertex of the file. A face may have any number of vertices (tinyobjloader's own count stops at 255; see
// scene/obj_faces.h); an error names the file's line.
void read_meshes(const TomlReader& r, Scene& scene);

}  // namespace hsr::algo
