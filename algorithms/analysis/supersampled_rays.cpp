// SPDX-License-Identifier: MIT
#include "analysis/supersampled_rays.h"

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/parallel.h"
#include "core/plane.h"

namespace hsr::analysis {

namespace {

using algo::Vec3;

struct WorldPolygon {
    std::vector<Vec3> v;
    Vec3 normal;
    glm::dvec3 colour;
    double opacity;
};

std::vector<WorldPolygon> world_polygons(const algo::Scene& s) {
    std::vector<WorldPolygon> out;
    for (const algo::ScenePolygon& p : s.polygons) {
        if (p.vertices.size() < 3) continue;
        WorldPolygon w;
        for (const auto& v : p.vertices) w.v.push_back(Vec3(v));
        Vec3 n(0);  // Newell's normal: robust for any convex polygon
        for (std::size_t k = 0; k < w.v.size(); ++k) n += glm::cross(w.v[k], w.v[(k + 1) % w.v.size()]);
        if (glm::length(n) == 0) continue;
        w.normal = glm::normalize(n);
        w.colour = glm::dvec3(p.color.r, p.color.g, p.color.b) / 255.0;
        w.opacity = p.opacity;
        out.push_back(std::move(w));
    }
    return out;
}

// Where the segment a→b meets the polygon, as a parameter in [0, 1]; < 0 where it does not.
double hit(const WorldPolygon& p, Vec3 a, Vec3 b) {
    const double denominator = glm::dot(p.normal, b - a);
    if (denominator == 0) return -1;
    const double t = glm::dot(p.normal, p.v[0] - a) / denominator;
    if (!(t >= 0 && t <= 1)) return -1;
    const Vec3 q = a + t * (b - a);
    for (std::size_t k = 0; k < p.v.size(); ++k)  // inside every edge (counter-clockwise about the normal)
        if (glm::dot(glm::cross(p.v[(k + 1) % p.v.size()] - p.v[k], q - p.v[k]), p.normal) < 0) return -1;
    return t;
}

glm::dvec4 pixel(const std::vector<WorldPolygon>& polygons, const glm::dmat4& to_world, algo::Viewport vp, int x, int y, int s) {
    glm::dvec4 sum(0);
    std::vector<std::pair<double, const WorldPolygon*>> hits;
    for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i) {
            const double px = x + (i + 0.5) / s, py = y + (j + 0.5) / s;
            const double nx = 2 * px / vp.width - 1, ny = 1 - 2 * py / vp.height;  // the rasterisers' viewport map
            const glm::dvec4 a = to_world * glm::dvec4(nx, ny, -1, 1), b = to_world * glm::dvec4(nx, ny, 1, 1);
            const Vec3 from = Vec3(a) / a.w, to = Vec3(b) / b.w;  // the near plane to the far plane
            hits.clear();
            for (const WorldPolygon& p : polygons)
                if (const double t = hit(p, from, to); t >= 0) hits.emplace_back(t, &p);
            std::sort(hits.begin(), hits.end(), [](const auto& u, const auto& v) { return u.first < v.first; });
            glm::dvec3 colour(0);
            double light = 1;
            for (const auto& [t, p] : hits) {
                colour += light * p->opacity * p->colour;
                light *= 1 - p->opacity;
            }
            sum += glm::dvec4(colour, 1 - light);
        }
    return sum / double(s * s);
}

}  // namespace

glm::dvec4 supersampled_pixel(const algo::Scene& scene, algo::Viewport viewport, int x, int y, int rays_per_side) {
    return pixel(world_polygons(scene), glm::inverse(algo::view_projection(scene.camera)), viewport, x, y, rays_per_side);
}

std::vector<glm::dvec4> supersampled_image(const algo::Scene& scene, algo::Viewport viewport, int rays_per_side) {
    const std::vector<WorldPolygon> polygons = world_polygons(scene);
    const glm::dmat4 to_world = glm::inverse(algo::view_projection(scene.camera));
    std::vector<glm::dvec4> out(std::size_t(viewport.width) * std::size_t(viewport.height));
    algo::for_each_chunk(std::size_t(viewport.height), 1, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t y = begin; y < end; ++y)
            for (int x = 0; x < viewport.width; ++x)
                out[y * std::size_t(viewport.width) + std::size_t(x)] = pixel(polygons, to_world, viewport, x, int(y), rays_per_side);
    });
    return out;
}

}  // namespace hsr::analysis
