// SPDX-License-Identifier: MIT
#include "render/zbuffer_renderer.h"

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "render/frustum.h"
#include "render/palette.h"
#include "render/scene_color.h"
#include "state/strings.h"

namespace hsr::viz {

using algo::Vec3;

void draw_zbuffer_3d(const ZView& v, const algo::Scene& scene, LineBatches& out, std::vector<Label>& labels) {
    const SceneColors colors(scene);
    for (const auto& p : scene.polygons) {
        for (std::size_t k = 1; k + 1 < p.vertices.size(); ++k)
            out.faint.triangle(glm::vec3(p.vertices[0]), glm::vec3(p.vertices[k]), glm::vec3(p.vertices[k + 1]),
                               colors(p.id, 0.35f));
        for (std::size_t k = 0; k < p.vertices.size(); ++k)
            out.faint.line(glm::vec3(p.vertices[k]), glm::vec3(p.vertices[(k + 1) % p.vertices.size()]), colors(p.id, 1));
    }
    draw_frustum(scene.camera, out.faint);
    out.bold.point(glm::vec3(scene.camera.eye), palette::eye);
    labels.push_back({glm::vec3(scene.camera.eye), tr("view.eye"), palette::eye});
    // The image stands at a depth just behind the farthest vertex (within the view volume)
    const Vec3 forward = glm::normalize(scene.camera.target - scene.camera.eye);
    double depth = scene.camera.near;
    for (const auto& p : scene.polygons)
        for (const auto& q : p.vertices) depth = std::max(depth, glm::dot(Vec3(q) - scene.camera.eye, forward));
    const double s = std::clamp((depth * 1.1 - scene.camera.near) / (scene.camera.far - scene.camera.near), 0.0, 1.0);
    const auto at = [&](double px, double py) {  // a point of the image, in pixels (y down)
        const algo::Ray r = algo::ndc_ray(scene.camera, 2 * px / v.viewport.width - 1, 1 - 2 * py / v.viewport.height);
        return glm::vec3(r.origin + s * r.direction);
    };
    for (int y = 0; y < v.viewport.height; ++y)
        for (int x = 0; x < v.viewport.width; ++x) {
            const std::int32_t o = v.owner[std::size_t(y) * std::size_t(v.viewport.width) + std::size_t(x)];
            const glm::vec4 c = o < 0 ? glm::vec4(0.16f, 0.17f, 0.2f, 0.9f) : colors((*v.polygons)[std::size_t(o)].id, 0.95f);
            const glm::vec3 a = at(x, y), b = at(x + 1, y), cc = at(x + 1, y + 1), d = at(x, y + 1);
            out.faint.triangle(a, b, cc, c);
            out.faint.triangle(a, cc, d, c);
        }
    if (v.pixel_x >= 0) {  // the pixel under test, and its ray from the eye
        const glm::vec3 centre = at(v.pixel_x + 0.5, v.pixel_y + 0.5);
        out.bold.line(glm::vec3(scene.camera.eye), centre, palette::current_edge);
        out.bold.point(centre, palette::current_edge);
    }
}

}  // namespace hsr::viz
