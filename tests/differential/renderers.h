// SPDX-License-Identifier: MIT
// Every hidden-surface algorithm and setting of hsrviz as a function from a scene to an id image, for the
// differential test (the window-free ones: OpenGL is added by the test that has a context).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "pixel_classes.h"
#include "raycast/ray_cast.h"
#include "zbuffer/depth_format.h"

namespace hsr::test {

// What one renderer drew: the id image, the outlines of the parts it split polygons into, and whether it stopped
// at a bound (its picture is then unfinished).
struct Drawn {
    std::vector<algo::SceneId> ids;
    Outlines parts;
    bool bounded = false;
};

struct Renderer {
    std::string name;
    std::vector<algo::DepthFormat> formats;  // the formats whose codes decide a depth tie with it
    std::function<Drawn(const algo::Scene&, algo::Viewport)> draw;
};

// The z-buffer in every depth format, the scan line (hybrid in every format, and classic), the ray cast with each acceleration, the BSP painter with
// each splitter rule, depth sort, and the culling pipeline's conservative stages before its z-buffer.
std::vector<Renderer> cpu_renderers();
// The plainest reference: the double-precision ray cast with no acceleration.
Drawn ray_cast(const algo::Scene& s, algo::Viewport vp, algo::Acceleration a = algo::Acceleration::none);

}  // namespace hsr::test
