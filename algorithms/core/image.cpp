#include "core/image.h"

#include <algorithm>
#include <cmath>

#include "clipping/sutherland_hodgman.h"

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
                          std::uint16_t id, Color color) {
    ClipPolygon clip{id, {}};
    for (const Vec3& v : polygon) clip.vertices.push_back(view_projection * glm::dvec4(v, 1.0));
    const PolygonClip visible = sutherland_hodgman(std::move(clip), {.space = ClipSpace::homogeneous}).run_to_end();
    if (visible.vertices.size() < 3) return 0;

    // NDC → pixel coordinates (x right, y down), pixel centres at +0.5
    std::vector<glm::dvec2> screen;
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const Vec4& v : visible.vertices) {
        const glm::dvec2 s((v.x / v.w + 1) * 0.5 * image.width, (1 - v.y / v.w) * 0.5 * image.height);
        screen.push_back(s);
        x0 = std::min(x0, s.x), x1 = std::max(x1, s.x), y0 = std::min(y0, s.y), y1 = std::max(y1, s.y);
    }
    const int ix0 = std::max(0, int(std::floor(x0))), ix1 = std::min(image.width - 1, int(std::ceil(x1)));
    const int iy0 = std::max(0, int(std::floor(y0))), iy1 = std::min(image.height - 1, int(std::ceil(y1)));
    std::size_t covered = 0;
    for (int y = iy0; y <= iy1; ++y)
        for (int x = ix0; x <= ix1; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            bool in = false;  // crossing number
            for (std::size_t i = 0, j = screen.size() - 1; i < screen.size(); j = i++) {
                const glm::dvec2 &a = screen[i], &b = screen[j];
                if ((a.y > py) != (b.y > py) && px < (b.x - a.x) * (py - a.y) / (b.y - a.y) + a.x) in = !in;
            }
            if (!in) continue;
            const std::size_t k = std::size_t(y) * std::size_t(image.width) + std::size_t(x);
            image.ids[k] = id;
            image.rgb[3 * k] = color.r, image.rgb[3 * k + 1] = color.g, image.rgb[3 * k + 2] = color.b;
            ++covered;
        }
    return covered;
}

}  // namespace hsr::algo
