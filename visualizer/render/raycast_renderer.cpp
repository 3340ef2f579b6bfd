// SPDX-License-Identifier: MIT
#include "render/raycast_renderer.h"

#include <array>
#include <cstdio>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "render/frustum.h"
#include "render/palette.h"
#include "render/scene_color.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using algo::Vec3;

void box(LineBatch& out, Vec3 lo, Vec3 hi, glm::vec4 colour) {
    const auto corner = [&](int i) { return glm::vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
    for (int i = 0; i < 8; ++i)
        for (int axis = 1; axis < 8; axis <<= 1)
            if (!(i & axis)) out.line(corner(i), corner(i | axis), colour);
}

}  // namespace

void draw_raycast_view(const RayView& v, const algo::Scene& scene, LineBatches& out, std::vector<Label>& labels) {
    const SceneColors colors(scene);
    // The scene's polygons, the nearest hit so far drawn stronger
    for (std::size_t i = 0; i < scene.polygons.size(); ++i) {
        const auto& p = scene.polygons[i];
        const bool nearest = int(i) == v.nearest, tested = int(i) == v.tested;
        for (std::size_t k = 1; k + 1 < p.vertices.size(); ++k)
            out.faint.triangle(glm::vec3(p.vertices[0]), glm::vec3(p.vertices[k]), glm::vec3(p.vertices[k + 1]),
                               colors(p.id, nearest ? 0.7f : 0.25f));
        for (std::size_t k = 0; k < p.vertices.size(); ++k)
            (tested ? out.bold : out.faint)
                .line(glm::vec3(p.vertices[k]), glm::vec3(p.vertices[(k + 1) % p.vertices.size()]),
                      tested ? palette::current_edge : colors(p.id, 1));
    }
    // each polygon named as the questions and the narration name it, when there are few enough to read
    if (scene.polygons.size() <= 12)
        for (const auto& p : scene.polygons) {
            Vec3 centre(0);
            for (const auto& q : p.vertices) centre += Vec3(q);
            labels.push_back({glm::vec3(centre / double(p.vertices.size())), tr("raycast.label_polygon", {{"id", std::to_string(p.id)}}),
                              colors(p.id, 1)});
        }
    draw_frustum(scene.camera, out.faint);
    out.bold.point(glm::vec3(scene.camera.eye), palette::eye);
    labels.push_back({glm::vec3(scene.camera.eye), tr("view.eye"), palette::eye});
    // The grid and the cells the ray has walked
    if (v.grid) {
        const algo::Grid& g = *v.grid;
        box(out.faint, g.box.lo, g.box.hi, glm::vec4(0.6f, 0.6f, 0.65f, 0.4f));
        // a classroom grid (a few cells a side) with its inner planes outlined, so that its cells can be counted
        if (g.cells.x <= 8 && g.cells.y <= 8 && g.cells.z <= 8)
            for (int a = 0; a < 3; ++a)
                for (int i = 1; i < g.cells[a]; ++i) {
                    Vec3 lo = g.box.lo, hi = g.box.hi;
                    lo[a] = hi[a] = g.box.lo[a] + double(i) * g.size[a];
                    box(out.faint, lo, hi, glm::vec4(0.6f, 0.6f, 0.65f, 0.22f));
                }
        for (std::size_t i = 0; i < v.cells.size(); ++i) {
            const Vec3 lo = g.box.lo + Vec3(v.cells[i]) * g.size;
            const bool last = i + 1 == v.cells.size();
            box(last ? out.bold : out.faint, lo, lo + g.size, last ? palette::parameter : glm::vec4(0.34f, 0.71f, 0.91f, 0.6f));
            if (last)  // the cell the ray is in, named as the narration names it
                labels.push_back({glm::vec3(lo + g.size), tr("raycast.label_cell", {{"x", std::to_string(v.cells[i].x)}, {"y", std::to_string(v.cells[i].y)},
                                                                                   {"z", std::to_string(v.cells[i].z)}}),
                                  palette::parameter});
        }
    }
    // The octree: while it is built, its leaves so far (green: few primitives, amber: a voxel) and the cell being
    // examined; then its leaves faintly, and the node the ray entered last
    for (std::size_t i = 0; i < v.octree.size(); ++i) {
        const OctreeCellView& c = v.octree[i];
        const bool examined = int(i) == v.examined, entered = int(i) == v.entered;
        if (examined || entered) continue;  // drawn last, on top
        if (!c.leaf) continue;  // a split cell is drawn by its children
        const bool voxel = c.reason == algo::OctreeStop::voxel_size;
        const float alpha = v.octree_built ? 0.18f : 0.45f;
        box(out.faint, c.lo, c.hi, voxel ? glm::vec4(0.9f, 0.62f, 0.0f, alpha) : glm::vec4(0.35f, 0.8f, 0.55f, alpha));
    }
    if (v.examined >= 0 && std::size_t(v.examined) < v.octree.size()) {
        const OctreeCellView& c = v.octree[std::size_t(v.examined)];
        box(out.bold, c.lo, c.hi, palette::current_edge);
        char buf[64];
        std::snprintf(buf, sizeof buf, "%d: %u", v.examined, c.primitives);
        labels.push_back({glm::vec3(c.hi), buf, palette::current_edge});
    }
    if (v.entered >= 0 && std::size_t(v.entered) < v.octree.size())
        box(out.bold, v.octree[std::size_t(v.entered)].lo, v.octree[std::size_t(v.entered)].hi, palette::parameter);
    // The ray: solid up to the nearest hit, faint beyond
    if (v.ray_x >= 0) {
        const double t = std::min(v.nearest_t, 1.0);
        const Vec3 hit = v.origin + t * v.direction;
        out.bold.line(glm::vec3(v.origin), glm::vec3(hit), palette::working);
        if (t < 1) {
            out.faint.line(glm::vec3(hit), glm::vec3(v.origin + v.direction), glm::vec4(1, 1, 1, 0.3f));
            out.bold.point(glm::vec3(hit), palette::intersection);
            char buf[48];
            std::snprintf(buf, sizeof buf, "nearest t = %.4g", t);
            labels.push_back({glm::vec3(hit), buf, palette::intersection});
        }
    }
}

}  // namespace hsr::viz
