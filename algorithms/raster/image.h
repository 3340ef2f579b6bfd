// SPDX-License-Identifier: MIT
// An image of colours and of visible primitive ids (0 is background), and the painter's fill: a polygon painted
// over whatever is there, as the hidden-surface algorithms that produce an order (BSP, depth sort) draw.
// Pixels are covered as the z-buffer covers them (raster/screen_polygon.h: clipped in homogeneous clip space first,
// pixel centres, top-left rule), so a painter's image and a z-buffer image of the same scene agree pixel for pixel.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/plane.h"
#include "scene/scene.h"

namespace hsr::algo {

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;   // row 0 is the top
    std::vector<SceneId> ids;  // the scene's id of the primitive painted last, 0 for background

    Image(int w, int h, Color background = {0, 0, 0});
    SceneId id(int x, int y) const { return ids[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// Paints the polygon (world space, 3 or more vertices) seen through view_projection. Returns the pixels covered.
std::size_t paint_polygon(Image& image, const glm::dmat4& view_projection, std::span<const Vec3> polygon,
                          SceneId id, Color color);
// The same for a polygon given in clip space (x, y, z, w), or in normalised device coordinates with w = 1. With
// opacity α < 1 the colour goes "over" what is there (premultiplied: c = α·colour + (1 − α)·c), as a painter's
// algorithm drawing back to front composites translucent polygons; the id becomes the polygon's either way.
std::size_t paint_clip_polygon(Image& image, std::vector<glm::dvec4> clip, SceneId id, Color color, double opacity = 1);

}  // namespace hsr::algo
