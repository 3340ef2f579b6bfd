// SPDX-License-Identifier: MIT
// Where the clip volume and its 27 outcode regions lie in the scene's world, for the clipping view to draw:
// "6 bits are used to code the 27 partitions of 3D space defined by the view frustum planes". Plain geometry, no
// GL: the test checks each region's code against mkcode of a point in it.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "clipping/clip_space.h"
#include "scene/scene.h"

namespace hsr::viz {

// Clip space → world space for a scene's camera; none for points the camera maps to infinity (w = 0).
class ClipToWorld {
public:
    explicit ClipToWorld(const algo::Camera& c);
    std::optional<glm::dvec3> operator()(const algo::Vec4& clip) const;

private:
    glm::dmat4 inverse_;
};

struct OutcodeRegion {
    glm::dvec3 at;       // a point well inside the region, where its label goes
    algo::Outcode code;  // the six bits every point of the region gets (no w bit: the regions are the six planes')
};

// The 27 regions, each with a point in it: in x and y at NDC −2, 0 or 2; in depth before the near plane (half way
// to the eye in a perspective view), between the planes, or past the far plane.
std::vector<OutcodeRegion> outcode_regions(const algo::Camera& camera);

// The lines that cut space into them: the volume's edges drawn on past its corners, so that the near and far
// planes carry a 3 × 3 grid and the side edges run from the eye (or from before the box) to past the far plane.
std::vector<std::pair<glm::dvec3, glm::dvec3>> outcode_region_lines(const algo::Camera& camera);

}  // namespace hsr::viz
