// SPDX-License-Identifier: MIT
// Writing a scene back to TOML, in the format load_scene reads (geometry, camera, floor plan; the [expect] table and
// [[meshes]] are not kept: a saved scene holds the meshes' faces as polygons). For the window's export and for
// saving an edited scene; a test holds load(save(scene)) to the scene itself.
#pragma once

#include <string>

#include "scene/scene.h"

namespace hsr::algo {

std::string scene_toml(const Scene& scene);

}  // namespace hsr::algo
