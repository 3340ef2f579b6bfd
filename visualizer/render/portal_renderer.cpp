// SPDX-License-Identifier: MIT
#include "render/portal_renderer.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "render/palette.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

glm::vec4 colour(const algo::Color& c, float alpha) { return {c.r / 255.f, c.g / 255.f, c.b / 255.f, alpha}; }

void outline(LineBatch& out, const std::vector<algo::Vec3>& v, glm::vec4 c) {
    for (std::size_t k = 0; k < v.size(); ++k) out.line(glm::vec3(v[k]), glm::vec3(v[(k + 1) % v.size()]), c);
}

}  // namespace

void portal_view_bounds(const algo::CellModel& m, glm::vec3& centre, float& radius) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const auto& p : m.polygons)
        for (const auto& v : p.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
    centre = glm::vec3((lo + hi) / 2.0);
    radius = std::max(1.0f, float(glm::length(hi - lo) / 2));
}

void draw_portal_view(const PortalView& v, LineBatches& out, std::vector<Label>& labels) {
    const auto& m = v.world->model;
    for (std::size_t k = 0; k < m.polygons.size(); ++k) {
        const auto& p = m.polygons[k];
        if (v.fate[k] == PolygonFate::drawn) {
            for (std::size_t i = 1; i + 1 < p.vertices.size(); ++i)
                out.faint.triangle(glm::vec3(p.vertices[0]), glm::vec3(p.vertices[i]), glm::vec3(p.vertices[i + 1]), colour(p.color, 0.8f));
            outline(out.faint, p.vertices, colour(p.color, 1));
        } else {
            outline(out.faint, p.vertices, colour(p.color, v.fate[k] == PolygonFate::untouched ? 0.25f : 0.12f));
        }
    }
    for (std::size_t k = 0; k < m.portals.size(); k += 2) outline(out.faint, m.portals[k].opening, palette::plane_edge);
    const glm::vec3 eye(v.camera.eye);
    out.bold.point(eye, palette::eye);
    labels.push_back({eye, tr("view.eye"), palette::eye});
    // the narrowed frusta: rays from the eye through the corners of each one's cross-section, as far as the opening it
    // was narrowed to and a little beyond; with bounding-box frusta the exact one (through the opening's visible
    // part) beside it, thin, so that what the box adds shows
    for (std::size_t i = 0; i < v.passed.size(); ++i) {
        const auto& n = v.passed[i];
        const float reach = 1.5f * float(glm::length(algo::centroid(n.visible_part) - v.camera.eye));
        for (const auto& q : n.section) out.bold.line(eye, eye + glm::normalize(glm::vec3(q) - eye) * reach, palette::plane_edge);
        if (!wider_than_exact(n, v.camera)) continue;
        const std::vector<algo::Vec3> exact = exact_section(n, v.camera);
        for (const auto& q : exact) out.faint.line(eye, eye + glm::normalize(glm::vec3(q) - eye) * reach, palette::inside);
        outline(out.bold, n.visible_part, palette::inside);
        if (i + 1 == v.passed.size() && !n.section.empty() && !exact.empty()) {  // named once, at the far end of a ray
            labels.push_back({eye + glm::normalize(glm::vec3(n.section[0]) - eye) * reach, tr("portals.label_box_frustum"), palette::plane_edge});
            labels.push_back({eye + glm::normalize(glm::vec3(exact[0]) - eye) * reach, tr("portals.label_exact_frustum"), palette::inside});
        }
    }
    // the polygons the narration and the questions name, by their ids
    for (std::uint32_t k : named_polygons(v))
        labels.push_back({glm::vec3(algo::centroid(m.polygons[k].vertices)), tr("portals.label_polygon", {{"id", std::to_string(m.polygons[k].id)}}),
                          palette::working});
    if (v.cell >= 0) {
        const auto& c = m.cells[std::size_t(v.cell)];
        algo::Vec2 mean(0);
        for (const auto& p : c.outline) mean += p / double(c.outline.size());
        labels.push_back({glm::vec3(algo::world_point(mean, m.height)), "portal_render(" + c.name + ")", palette::current_edge});
    }
}

}  // namespace hsr::viz
