// SPDX-License-Identifier: MIT
#include "raster/image.h"

#include <algorithm>
#include <cmath>

#include "raster/screen_polygon.h"

namespace hsr::algo {

Image::Image(int w, int h, Color background)
    : width(w), height(h), rgb(std::size_t(w) * std::size_t(h) * 3), ids(std::size_t(w) * std::size_t(h), 0) {
    for (std::size_t i = 0; i < ids.size(); ++i) {
        rgb[3 * i] = background.r;
        rgb[3 * i + 1] = background.g;
        rgb[3 * i + 2] = background.b;
    }
}

std::size_t paint_polygon(Image& image, const glm::dmat4& view_projection, std::span<const Vec3> polygon,
                          SceneId id, Color color) {
    std::vector<glm::dvec4> clip;
    for (const Vec3& v : polygon) clip.push_back(view_projection * glm::dvec4(v, 1.0));
    return paint_clip_polygon(image, std::move(clip), id, color);
}

std::size_t paint_clip_polygon(Image& image, std::vector<glm::dvec4> clip, SceneId id, Color color, double opacity) {
    const auto over = [&](std::uint8_t& dst, std::uint8_t src) {
        dst = std::uint8_t(std::lround(opacity * src + (1 - opacity) * dst));
    };
    const Viewport viewport{image.width, image.height};
    const ScreenPolygon p = project_polygon(id, color, std::move(clip), viewport);
    std::size_t covered = 0;
    for (int y = p.row_begin; y < p.row_end; ++y) {
        const Span span = span_on_row(p, y, viewport);
        for (int x = span.begin; x < span.end; ++x, ++covered) {
            const std::size_t k = std::size_t(y) * std::size_t(image.width) + std::size_t(x);
            image.ids[k] = id;
            over(image.rgb[3 * k], color.r), over(image.rgb[3 * k + 1], color.g), over(image.rgb[3 * k + 2], color.b);
        }
    }
    return covered;
}

}  // namespace hsr::algo
