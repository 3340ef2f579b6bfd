// SPDX-License-Identifier: MIT
// Why two images of the same scene differ at a pixel. Two renderers may rightly disagree where a pixel's centre
// lies within rounding of a polygon's outline (edge) or where the two polygons they show lie within a few depth
// codes of each other there (depth tie); anywhere else one of them is wrong (unexplained).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "raster/screen_polygon.h"
#include "scene/scene.h"
#include "zbuffer/depth_format.h"

namespace hsr::test {

// A polygon on the screen: its clip-space outline clipped to the near and far planes, then divided: x and y in
// pixels (y down), and the window depth d ∈ [0, 1] (0 at near), which is affine on the screen.
struct Outline {
    std::vector<glm::dvec3> screen;
};
Outline screen_outline(std::span<const glm::dvec4> clip, algo::Viewport vp);

// Within `distance` pixels of one of the outline's edges.
bool near_outline(const Outline& o, glm::dvec2 at, double distance);
// The window depth of the outline's plane at a point; none for a polygon seen edge-on.
std::optional<double> depth_at(const Outline& o, glm::dvec2 at);

// Outlines by scene id: a scene's polygons, or the parts a painter split them into.
using Outlines = std::unordered_map<algo::SceneId, std::vector<Outline>>;
Outlines scene_outlines(const algo::Scene& s, algo::Viewport vp);
void add_outline(Outlines& to, algo::SceneId id, std::span<const glm::dvec4> clip, algo::Viewport vp);

enum class PixelClass { same, edge, tie, unexplained };

// How depths are told apart: two depths tie when they lie within `codes` codes of each other in any of `formats`.
struct TieRule {
    std::vector<algo::DepthFormat> formats;
    algo::DepthRange range;
    bool perspective = true;
    std::uint64_t codes = 4;
};

constexpr double edge_distance = 1.0 / 64;  // pixels

// Pixel (x, y) shows `a` in one image and `b` in the other (0: background). `parts` holds the outlines of the
// pieces one renderer drew (its split polygons), or is empty.
PixelClass classify(int x, int y, algo::SceneId a, algo::SceneId b, const Outlines& scene, const Outlines& parts, const TieRule& tie);

// Two id images of one scene compared pixel by pixel: how many differ, and of those how many are edges, depth ties
// and unexplained. `first_unexplained` receives up to `keep` of the unexplained pixels, as "(x, y): a, reference b".
struct Tally {
    std::uint64_t compared = 0, differ = 0, edge = 0, tie = 0, unexplained = 0;
    Tally& operator+=(const Tally& t);
};
Tally compare_images(const std::vector<algo::SceneId>& ours, const std::vector<algo::SceneId>& reference, algo::Viewport vp,
                     const Outlines& scene, const Outlines& parts, const TieRule& tie, std::vector<std::string>* first_unexplained = nullptr,
                     std::size_t keep = 0);

}  // namespace hsr::test
