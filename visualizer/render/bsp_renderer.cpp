// SPDX-License-Identifier: MIT
#include "render/bsp_renderer.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "render/palette.h"
#include "render/scene_color.h"
#include "state/bsp_painting.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using algo::Vec3;

// The box round the scene's polygons, and with `eye` round the eye as well.
void bounds(const BspView& v, Vec3& lo, Vec3& hi, bool eye = true) {
    lo = Vec3(1e300), hi = Vec3(-1e300);
    for (const auto& p : v.polygons)
        for (const Vec3& x : *p.vertices) lo = glm::min(lo, x), hi = glm::max(hi, x);
    if (eye) lo = glm::min(lo, v.eye), hi = glm::max(hi, v.eye);
}

// The region of a node in 2D: the scene's box, cut by the half-plane of each ancestor on the node's side.
std::vector<Vec3> region_2d(const BspView& v, int node, const Vec3& lo, const Vec3& hi) {
    const double m = 0.15 * std::max(hi.x - lo.x, hi.y - lo.y) + 0.5;
    std::vector<Vec3> region = {{lo.x - m, lo.y - m, 0}, {hi.x + m, lo.y - m, 0}, {hi.x + m, hi.y + m, 0},
                                {lo.x - m, hi.y + m, 0}};
    const algo::Tolerance tol{1e-12};
    for (int n = node; n >= 0 && v.nodes[std::size_t(n)].parent >= 0; n = v.nodes[std::size_t(n)].parent) {
        const BspNodeView& child = v.nodes[std::size_t(n)];
        const algo::SplitParts parts = algo::split(v.nodes[std::size_t(child.parent)].plane, region, tol);
        region = child.side_of_parent == algo::Side::back ? parts.back : parts.front;
        if (region.size() < 3) return {};
    }
    return region;
}

// The splitting line of a 2D node, clipped to its region: a long segment along the line, cut by the region's edges.
std::vector<Vec3> split_line_2d(const BspView& v, int node, const Vec3& lo, const Vec3& hi) {
    const std::vector<Vec3> region = region_2d(v, node, lo, hi);
    if (region.empty()) return {};
    const algo::Plane& p = v.nodes[std::size_t(node)].plane;
    const Vec3 along(-p.n.y, p.n.x, 0), on = -p.d * p.n;
    const double far = 10 * glm::length(hi - lo) + 10;
    std::vector<Vec3> segment = {on - far * along, on + far * along};
    const algo::Tolerance tol{1e-12};
    for (std::size_t i = 0; i < region.size() && segment.size() == 2; ++i) {  // keep the part inside each edge
        const Vec3 a = region[i], b = region[(i + 1) % region.size()];
        const Vec3 inward = glm::normalize(Vec3(-(b - a).y, (b - a).x, 0));  // the region is counter-clockwise
        segment = algo::split({inward, -glm::dot(inward, a)}, segment, tol).front;
    }
    return segment.size() == 2 ? segment : std::vector<Vec3>{};
}

// A square in the plane, centred where the scene's centre projects onto it, large enough to cross the scene.
std::vector<Vec3> plane_quad(const algo::Plane& p, const Vec3& lo, const Vec3& hi) {
    const Vec3 c = (lo + hi) * 0.5, on = c - p.n * p.distance(c);
    const double r = 0.35 * glm::length(hi - lo) + 0.5;
    const Vec3 u = glm::normalize(glm::cross(p.n, std::abs(p.n.y) < 0.9 ? Vec3(0, 1, 0) : Vec3(1, 0, 0)));
    const Vec3 w = glm::cross(p.n, u);
    return {on - r * u - r * w, on + r * u - r * w, on + r * u + r * w, on - r * u + r * w};
}

}  // namespace

void draw_bsp_view(const BspView& v, const algo::Scene& scene, LineBatches& out, std::vector<Label>& labels) {
    const SceneColors colors(scene);
    Vec3 lo, hi;
    bounds(v, lo, hi);
    const double tick = 0.05 * glm::length(hi - lo) + 0.05;  // the length of a front-side tick

    // the splitting planes: in 2D every node's line in its region, in 3D the current node's plane
    if (v.two_d) {
        // regions shaded by depth: every node's region is filled faintly, so deeper regions come out lighter
        for (std::size_t n = 0; n < v.nodes.size(); ++n) {
            const auto region = region_2d(v, int(n), lo, hi);
            for (std::size_t k = 1; k + 1 < region.size(); ++k)
                out.faint.triangle(glm::vec3(region[0]), glm::vec3(region[k]), glm::vec3(region[k + 1]),
                                   glm::vec4(0.55f, 0.65f, 0.85f, 0.07f));
        }
        for (std::size_t n = 0; n < v.nodes.size(); ++n) {
            const auto line = split_line_2d(v, int(n), lo, hi);
            if (line.empty()) continue;
            const bool current = int(n) == v.current_node;
            (current ? out.bold : out.faint).line(glm::vec3(line[0]), glm::vec3(line[1]),
                                                  current ? palette::plane_edge : glm::vec4(0.55f, 0.6f, 0.7f, 0.8f));
        }
    } else if (v.current_node >= 0) {
        // the plane across the walls only: a square sized by the eye as well spread over the whole view and hid the
        // eye's side of it under its fill
        Vec3 walls_lo, walls_hi;
        bounds(v, walls_lo, walls_hi, false);
        const auto q = plane_quad(v.nodes[std::size_t(v.current_node)].plane, walls_lo, walls_hi);
        out.faint.triangle(glm::vec3(q[0]), glm::vec3(q[1]), glm::vec3(q[2]), palette::plane_fill);
        out.faint.triangle(glm::vec3(q[0]), glm::vec3(q[2]), glm::vec3(q[3]), palette::plane_fill);
        for (int i = 0; i < 4; ++i) out.faint.line(glm::vec3(q[std::size_t(i)]), glm::vec3(q[std::size_t((i + 1) % 4)]), palette::plane_edge);
        const Vec3 c = (q[0] + q[2]) * 0.5, n = v.nodes[std::size_t(v.current_node)].plane.n;  // its front side
        out.bold.line(glm::vec3(c), glm::vec3(c + n * (3 * tick)), palette::plane_edge);
        labels.push_back({glm::vec3(c + n * (3 * tick)), tr("bsp.front_label"), palette::plane_edge});
    }

    for (std::size_t i = 0; i < v.polygons.size(); ++i) {
        const BspPolygonView& p = v.polygons[i];
        if (p.replaced || !p.vertices) continue;
        const std::vector<Vec3>& vs = *p.vertices;
        const bool current = int(i) == v.current_polygon;
        const glm::vec4 fill = colors(p.source, p.drawn > 0 ? 0.9f : 0.3f);
        const glm::vec4 edge = current ? palette::current_edge : colors(p.source, 1.0f);
        if (vs.size() == 2) {
            (p.drawn > 0 || current ? out.bold : out.faint).line(glm::vec3(vs[0]), glm::vec3(vs[1]), edge);
        } else {
            for (std::size_t k = 1; k + 1 < vs.size(); ++k)  // a fan: the polygons are convex
                out.faint.triangle(glm::vec3(vs[0]), glm::vec3(vs[k]), glm::vec3(vs[k + 1]), fill);
            for (std::size_t k = 0; k < vs.size(); ++k)
                (current ? out.bold : out.faint).line(glm::vec3(vs[k]), glm::vec3(vs[(k + 1) % vs.size()]), edge);
        }
        // the front side, where the plane's normal points: a tick from the middle (a wall in 2D, a face in 3D)
        if (algo::Plane plane; algo::plane_of(vs, plane)) {
            const Vec3 c = algo::centroid(vs);
            (current ? out.bold : out.faint).line(glm::vec3(c), glm::vec3(c + plane.n * tick), edge);
        }
        std::string text = p.label;
        if (p.drawn > 0) text += "  #" + std::to_string(p.drawn);
        labels.push_back({glm::vec3(algo::centroid(vs)), text, current ? palette::current_edge : colors(p.source, 1.0f)});
    }
    out.bold.point(glm::vec3(v.eye), palette::eye);
    labels.push_back({glm::vec3(v.eye), tr("view.eye"), palette::eye});
    if (v.two_d) {  // what the first-person strip shows: the eye's field of view in the plan
        const algo::Camera c = strip_camera(scene.camera, 1);
        const Vec3 ahead = glm::normalize(c.target - c.eye);
        const double half = glm::radians(std::clamp(scene.camera.fov_y, 10.0, 150.0)) / 2, reach = 0.3 * glm::length(hi - lo);
        for (const double a : {-half, half}) {
            const Vec3 ray(std::cos(a) * ahead.x - std::sin(a) * ahead.y, std::sin(a) * ahead.x + std::cos(a) * ahead.y, 0);
            out.faint.line(glm::vec3(v.eye), glm::vec3(v.eye + reach * ray), palette::eye);
        }
    }
}

std::vector<glm::vec3> bsp_view_points(const BspView& v) {
    std::vector<glm::vec3> points = {glm::vec3(v.eye)};
    for (const auto& p : v.polygons)
        for (const Vec3& x : *p.vertices) points.emplace_back(x);
    return points;
}

void bsp_view_bounds(const BspView& v, glm::vec3& centre, float& radius) {
    Vec3 lo, hi;
    bounds(v, lo, hi);
    centre = glm::vec3((lo + hi) * 0.5);
    radius = std::max(0.5f, float(glm::length(hi - lo) * 0.5));
}

}  // namespace hsr::viz
