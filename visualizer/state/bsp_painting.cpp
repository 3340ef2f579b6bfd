// SPDX-License-Identifier: MIT
#include "state/bsp_painting.h"

#include <unordered_map>
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace hsr::viz {

using algo::Vec3;

algo::Camera strip_camera(const algo::Camera& plan, double aspect) {
    algo::Camera c = plan;
    c.projection = algo::Projection::perspective;
    c.eye.z = 0;
    Vec3 heading = plan.target - plan.eye;
    heading.z = 0;
    if (glm::length(heading) < 1e-12) heading = {0, 1, 0};
    c.target = c.eye + glm::normalize(heading);
    c.up = {0, 0, 1};
    c.aspect = aspect;
    // the camera's field of view spans the strip's width; its height is what that leaves
    const double across = glm::radians(std::clamp(plan.fov_y, 10.0, 150.0));
    c.fov_y = glm::degrees(2 * std::atan(std::tan(across / 2) / aspect));
    c.near = std::max(plan.near, 1e-3), c.far = std::max(plan.far, c.near * 10);
    return c;
}

double plan_size(const BspView& v) {
    Vec3 lo(1e300), hi(-1e300);
    for (const auto& p : v.polygons)
        for (const Vec3& x : *p.vertices) lo = glm::min(lo, x), hi = glm::max(hi, x);
    return v.polygons.empty() ? 1 : std::max(std::max(hi.x - lo.x, hi.y - lo.y), 1e-6);
}

algo::Image bsp_painted_so_far(const BspView& v, const algo::Scene& scene, algo::Viewport size) {
    algo::Image image(size.width, size.height, {26, 28, 33});
    if (v.two_d)  // a floor below the eye's height, so that a wall stands on something
        for (std::size_t k = image.rgb.size() / 2 / 3 * 3; k + 2 < image.rgb.size(); k += 3)
            image.rgb[k] = 44, image.rgb[k + 1] = 41, image.rgb[k + 2] = 36;
    std::vector<const BspPolygonView*> drawn;
    for (const auto& p : v.polygons)
        if (p.drawn > 0) drawn.push_back(&p);
    std::sort(drawn.begin(), drawn.end(), [](auto* a, auto* b) { return a->drawn < b->drawn; });
    // Front to back, a polygon goes only on pixels still empty (the notes' optimisation): the same pixels as
    // painting the ones drawn so far in the opposite order, each over what is there.
    if (v.order == algo::Order::front_to_back) std::reverse(drawn.begin(), drawn.end());
    // Colour and opacity by id (the first primitive with an id wins), looked up per drawn polygon in constant time
    std::unordered_map<std::int32_t, std::pair<algo::Color, double>> paint_of;
    for (const auto& seg : scene.segments) paint_of.try_emplace(seg.id, seg.color, 1.0);
    for (const auto& poly : scene.polygons) paint_of.try_emplace(poly.id, poly.color, poly.opacity);
    const auto colour_of = [&](std::int32_t id) {
        const auto found = paint_of.find(id);
        return found != paint_of.end() ? found->second : std::pair{algo::Color{200, 200, 200}, 1.0};
    };
    const double aspect = double(size.width) / std::max(size.height, 1);
    algo::Camera camera = scene.camera;
    camera.eye = v.eye;
    camera.aspect = aspect;
    if (v.two_d) camera = strip_camera(scene.camera, aspect);
    const glm::dmat4 to_clip = algo::view_projection(camera);
    // walls a third of the plan away fill 40 % of the strip's height (a wall near the eye fills all of it)
    const double h = 0.4 * std::tan(glm::radians(camera.fov_y) / 2) * plan_size(v) / 3;
    for (const BspPolygonView* p : drawn) {
        std::vector<Vec3> world = *p->vertices;
        if (world.size() == 2) {  // a wall of the plan, stood up around the eye's height
            const Vec3 up(0, 0, h);
            world = {world[0] - up, world[1] - up, world[1] + up, world[0] + up};
        }
        std::vector<glm::dvec4> clip;
        for (const Vec3& x : world) clip.push_back(to_clip * glm::dvec4(x, 1.0));
        const auto [colour, opacity] = colour_of(p->source);
        algo::paint_clip_polygon(image, std::move(clip), p->source, colour, opacity);
    }
    return image;
}

}  // namespace hsr::viz
