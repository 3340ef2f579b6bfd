// SPDX-License-Identifier: MIT
// hsrviz render SCENE --algorithm bsp|zbuffer|raycast|scanline|depth-sort [options] --out IMAGE.png [--ids IDS.png]
// SCENE is a scene file, or a generated scene: city:N, field:N or spheres:N (about N triangles). With --cull STAGES
// (zbuffer only) the culling pipeline runs first and prints one line per stage.
// Renders a scene's polygons headless with a hidden-surface algorithm and writes the colour image and, with --ids,
// the visible primitive id of every pixel (16-bit grey PNG, 0 for background, ids as the scene numbers them).
#pragma once

#include <optional>
#include <string>

namespace hsr::viz {

struct RenderOptions {
    std::string scene;
    std::string algorithm = "bsp";
    std::string splitter = "first";       // bsp
    std::string format = "int24";         // zbuffer and scanline: the depth format
    std::string acceleration = "grid";    // raycast: none, grid or octree
    std::optional<std::string> cull;      // zbuffer: the culling stages to run first ("back-face,frustum,…")
    std::string occluders = "planar";     // … the occluders stage's shapes: planar, proxy or solid
    bool fusion = false;                  // … and whether it fuses them
    std::optional<std::string> eye;  // "x,y,z": replaces the scene camera's eye (the target stays)
    std::string size = "512x512";
    std::string out;
    std::optional<std::string> ids;
};

int run_render(const RenderOptions& o);

}  // namespace hsr::viz
