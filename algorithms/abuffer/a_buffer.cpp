// SPDX-License-Identifier: MIT
#include "abuffer/a_buffer.h"

#include <algorithm>
#include <bit>
#include <string>

#include "core/numeric.h"

namespace hsr::algo {
namespace {

std::int64_t floor_pixel(std::int64_t subpixel) { return floor_div(subpixel, subpixels); }

// What one fragment gave its pixel in the resolve.
struct Share {
    std::uint32_t shown = 0;  // covered sub-samples that still let light through when it came
    double weight = 0;        // the light it added, averaged over the pixel
};

glm::dvec4 resolve_with_shares(std::vector<Fragment>& list, int m, std::vector<Share>* shares) {
    std::stable_sort(list.begin(), list.end(), [](const Fragment& a, const Fragment& b) { return a.depth < b.depth; });
    const int n = m * m;
    std::vector<double> light(std::size_t(n), 1.0);
    std::vector<glm::dvec3> colour(std::size_t(n), glm::dvec3(0));
    if (shares) shares->assign(list.size(), {});
    for (std::size_t k = 0; k < list.size(); ++k) {
        const Fragment& f = list[k];
        for (int s = 0; s < n; ++s) {
            if (!(f.mask >> s & 1)) continue;
            const double through = light[std::size_t(s)];
            if (shares && through > 0) ++(*shares)[k].shown, (*shares)[k].weight += through * f.opacity / n;
            colour[std::size_t(s)] += through * f.opacity * f.colour;
            light[std::size_t(s)] = through * (1 - f.opacity);
        }
    }
    glm::dvec4 pixel(0);
    for (int s = 0; s < n; ++s) pixel += glm::dvec4(colour[std::size_t(s)], 1 - light[std::size_t(s)]);
    return pixel / double(n);
}

}  // namespace

glm::dvec2 sub_sample(int x, int y, int i, int j, int m) { return {x + (i + 0.5) / m, y + (j + 0.5) / m}; }

std::uint64_t coverage_mask(const ScreenPolygon& p, int x, int y, int m) {
    if (p.status != ScreenStatus::drawn) return 0;
    std::uint64_t mask = 0;
    const std::int64_t step = subpixels / m;  // sub-pixels between sub-samples (m divides 256)
    const std::size_t n = p.vertices.size();
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            const std::int64_t px = std::int64_t(x) * subpixels + step * i + step / 2, py = std::int64_t(y) * subpixels + step * j + step / 2;
            bool inside = true;
            for (std::size_t k = 0; k < n && inside; ++k) {  // clockwise: inside every edge (the fill rule on an edge)
                const ScreenVertex &a = p.vertices[k], &b = p.vertices[(k + 1) % n];
                const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
                inside = dx * (py - a.y) - dy * (px - a.x) >= fill_rule_threshold(dx, dy);
            }
            if (inside) mask |= std::uint64_t(1) << (j * m + i);
        }
    return mask;
}

glm::dvec4 resolve(std::vector<Fragment>& list, int mask_size) { return resolve_with_shares(list, mask_size, nullptr); }

Steps<ABufferEvent, ABufferImage> a_buffer(Scene scene, Viewport viewport, ABufferOptions options) {
    const int m = options.mask_size;
    if (m != 1 && m != 2 && m != 4 && m != 8) throw InvalidInput("the A-buffer's mask size must be 1, 2, 4 or 8 (it is " + std::to_string(m) + ")");
    if (viewport.width < 1 || viewport.height < 1) throw InvalidInput("the A-buffer needs an image of at least 1 × 1 pixels");
    const glm::dmat4 to_clip = view_projection(scene.camera);
    ABufferImage out;
    out.viewport = viewport, out.mask_size = m;
    out.lists.resize(std::size_t(viewport.width) * std::size_t(viewport.height));
    co_yield ABufferStarted{viewport.width, viewport.height, m, std::uint32_t(scene.polygons.size())};

    // Scan: every polygon into fragments
    for (std::uint32_t i = 0; i < scene.polygons.size() && !out.bounded; ++i) {
        const ScenePolygon& sp = scene.polygons[i];
        for (std::size_t k = 0; k < sp.vertices.size(); ++k)
            require_finite(sp.vertices[k], "polygon " + std::to_string(sp.id) + " vertex " + std::to_string(k));
        std::uint32_t made = 0;
        if (sp.vertices.size() >= 3) {
            if (scene.coordinates == Coordinates::world) require_convex(sp);
            std::vector<glm::dvec4> clip;
            for (const auto& v : sp.vertices) clip.push_back(scene.coordinates == Coordinates::clip ? v : to_clip * v);
            const ScreenPolygon p = project_polygon(sp.id, sp.color, clip, viewport);
            if (p.status == ScreenStatus::drawn) {
                std::int64_t x0 = p.vertices[0].x, x1 = x0, y0 = p.vertices[0].y, y1 = y0;
                for (const auto& v : p.vertices) x0 = std::min(x0, v.x), x1 = std::max(x1, v.x), y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
                const int px0 = int(std::max<std::int64_t>(0, floor_pixel(x0))), px1 = int(std::min<std::int64_t>(viewport.width - 1, floor_pixel(x1)));
                const int py0 = int(std::max<std::int64_t>(0, floor_pixel(y0))), py1 = int(std::min<std::int64_t>(viewport.height - 1, floor_pixel(y1)));
                const glm::dvec3 colour(sp.color.r / 255.0, sp.color.g / 255.0, sp.color.b / 255.0);
                for (int y = py0; y <= py1 && !out.bounded; ++y)
                    for (int x = px0; x <= px1; ++x) {
                        const std::uint64_t mask = coverage_mask(p, x, y, m);
                        if (!mask) continue;
                        if (out.fragments == options.max_fragments) {
                            out.bounded = true;
                            break;
                        }
                        glm::dvec2 centre(0);  // of the covered sub-samples: where the fragment's depth is taken
                        for (int s = 0; s < m * m; ++s)
                            if (mask >> s & 1) centre += sub_sample(x, y, s % m, s / m, m);
                        const auto covered = std::uint32_t(std::popcount(mask));
                        centre /= double(covered);
                        const double depth = p.plane.at(centre.x, centre.y);
                        out.lists[std::size_t(y) * std::size_t(viewport.width) + std::size_t(x)].push_back({i, mask, depth, colour, sp.opacity});
                        ++out.fragments, ++made;
                        co_yield FragmentMade{i, x, y, mask, covered, std::uint32_t(m * m), depth};
                    }
            }
        }
        co_yield PolygonScanned{i, made, sp.opacity};
    }

    // Resolve: every pixel's list, front to back, sub-sample by sub-sample
    out.rgba.assign(out.lists.size(), glm::dvec4(0));
    std::uint32_t pixels = 0, longest = 0;
    std::vector<Share> shares;
    for (int y = 0; y < viewport.height; ++y)
        for (int x = 0; x < viewport.width; ++x) {
            const std::size_t k = std::size_t(y) * std::size_t(viewport.width) + std::size_t(x);
            std::vector<Fragment>& list = out.lists[k];
            if (list.empty()) continue;
            out.rgba[k] = resolve_with_shares(list, m, &shares);
            for (std::uint32_t order = 0; order < list.size(); ++order)
                co_yield FragmentResolved{x, y, list[order].polygon, order, std::uint32_t(std::popcount(list[order].mask)), shares[order].shown,
                                          shares[order].weight};
            ++pixels, longest = std::max(longest, std::uint32_t(list.size()));
            const glm::dvec4 c = out.rgba[k];
            co_yield PixelResolved{x, y, std::uint32_t(list.size()), c.x, c.y, c.z, c.w};
        }
    co_yield ABufferFinished{out.fragments, pixels, longest, out.bounded};
    co_return out;
}

}  // namespace hsr::algo
