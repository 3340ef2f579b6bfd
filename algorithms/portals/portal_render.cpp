// SPDX-License-Identifier: MIT
#include "portals/portal_render.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/numeric.h"

namespace hsr::algo {
namespace {

struct Render {
    const CellModel* model;
    Camera camera;
    const Pvs* pvs;
    PortalRenderOptions options;
    Vec3 eye, forward, right, up;
    std::uint32_t start = 0;
    std::vector<std::uint32_t> path;  // cells on the way to the one being visited
    PortalRenderResult out;
    bool stopped = false;
};


// R' = clip_poly(f, R): the part of R inside every plane of f (empty when nothing is left, or no area).
std::vector<Vec3> clip_poly(const std::vector<Plane>& f, std::vector<Vec3> poly, Tolerance tol) {
    for (const Plane& p : f) {
        if (poly.size() < 3) break;
        switch (classify(p, poly, tol)) {
            case PolygonSide::back: poly.clear(); break;
            case PolygonSide::spanning: poly = split(p, poly, tol).front; break;
            default: break;
        }
    }
    if (poly.size() < 3 || measure(poly) <= tol.epsilon * tol.epsilon) poly.clear();
    return poly;
}

// f' = clip_frustum(f, R), given R' = R clipped by f: the planes through the eye and each edge of R' (or of its
// bounding rectangle on the screen), then f's near and far planes.
std::vector<Plane> narrowed(const Render& r, const std::vector<Plane>& f, const std::vector<Vec3>& visible) {
    std::vector<Plane> out;
    const Vec3 inside = centroid(visible);
    if (r.options.bounding_box_frusta) {
        double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
        for (const Vec3& p : visible) {
            const Vec3 d = p - r.eye;
            const double z = glm::dot(d, r.forward), u = glm::dot(d, r.right) / z, v = glm::dot(d, r.up) / z;
            u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, v), v1 = std::max(v1, v);
        }
        out = {plane_through(r.right - u0 * r.forward, r.eye), plane_through(u1 * r.forward - r.right, r.eye),
               plane_through(r.up - v0 * r.forward, r.eye), plane_through(v1 * r.forward - r.up, r.eye)};
    } else {
        for (std::size_t i = 0; i < visible.size(); ++i) {
            const Vec3 n = glm::cross(visible[i] - r.eye, visible[(i + 1) % visible.size()] - r.eye);
            if (glm::length(n) <= r.model->tol.epsilon * r.model->tol.epsilon) continue;  // an edge in line with the eye
            Plane p = plane_through(n, r.eye);
            if (p.distance(inside) < 0) p = {-p.n, -p.d};
            out.push_back(p);
        }
    }
    out.insert(out.end(), f.end() - 2, f.end());  // near and far stay
    return out;
}

bool eye_in_opening(const Render& r, const Portal& p) {
    if (std::abs(p.plane.distance(r.eye)) > r.model->tol.epsilon) return false;
    return in_opening(p, r.eye, -r.model->tol.epsilon);
}

void draw_polygons(Render& r, std::uint32_t cell, const std::vector<Plane>& f, std::vector<PortalEvent>& events) {
    for (std::uint32_t k : r.model->cells[cell].polygons) {
        const CellPolygon& poly = r.model->polygons[k];
        // apply back-face cull
        if (poly.plane.distance(r.eye) <= r.model->tol.epsilon) {
            ++r.out.culled_back_face;
            events.push_back(CellPolygonCulled{k, CullReason::back_face});
            continue;
        }
        // apply frustum cull
        std::vector<Vec3> visible = clip_poly(f, poly.vertices, r.model->tol);
        if (visible.empty()) {
            ++r.out.culled_frustum;
            events.push_back(CellPolygonCulled{k, CullReason::frustum});
            continue;
        }
        r.out.drawn[k] = 1, ++r.out.draws;
        events.push_back(CellPolygonDrawn{k, std::move(visible)});
    }
}

Steps<PortalEvent, bool> render_cell(Render* r, std::uint32_t c, std::vector<Plane> f) {
    ++r->out.visits;
    {
        const PortalEvent visited = CellVisited{c, std::uint32_t(r->path.size()), f};
        co_yield visited;
    }
    // for each polygon R in c that is not a portal: back-face cull, frustum cull, render
    std::vector<PortalEvent> events;
    draw_polygons(*r, c, f, events);
    for (const PortalEvent& e : events) co_yield e;
    // for each portal R in c to a cell c' in the PVS: f' = clip_frustum(f, R); recurse if f' is not empty
    r->path.push_back(c);
    for (std::uint32_t k : r->model->cells[c].portals) {
        if (r->stopped) break;
        const Portal& portal = r->model->portals[k];
        PortalTested test{k, PortalVerdict::passed, {}, {}};
        const double eye_side = portal.plane.distance(r->eye);
        if (!r->pvs->visible(r->start, portal.to)) test.verdict = PortalVerdict::not_in_pvs;
        else if (std::find(r->path.begin(), r->path.end(), portal.to) != r->path.end()) test.verdict = PortalVerdict::on_path;
        else if (eye_in_opening(*r, portal)) test.visible_part = portal.opening, test.narrowed = f;  // standing in it: f' = f
        else if (eye_side >= -r->model->tol.epsilon) test.verdict = PortalVerdict::faces_away;
        else if ((test.visible_part = clip_poly(f, portal.opening, r->model->tol)).empty()) test.verdict = PortalVerdict::outside_frustum;
        else test.narrowed = narrowed(*r, f, test.visible_part);
        const bool passed = test.verdict == PortalVerdict::passed;
        std::vector<Plane> next = test.narrowed;
        {
            const PortalEvent tested = std::move(test);
            co_yield tested;
        }
        if (!passed) continue;
        ++r->out.portals_passed;
        if (r->path.size() >= r->options.max_depth || r->out.visits >= r->options.max_visits) {
            // Stop, and stay conservative: draw the rest of the PVS row against the original frustum
            r->stopped = r->out.bounded = true;
            co_yield PortalBoundReached{portal.to, r->path.size() >= r->options.max_depth ? r->options.max_depth : r->options.max_visits};
            const std::vector<Plane> all = view_frustum(r->camera);
            for (std::uint32_t cell : r->pvs->row(r->start)) {
                std::vector<PortalEvent> rest;
                draw_polygons(*r, cell, all, rest);
                for (const PortalEvent& e : rest) co_yield e;
            }
            break;
        }
        auto child = render_cell(r, portal.to, std::move(next));
        for (const auto& e : child) co_yield e;
    }
    r->path.pop_back();
    co_return true;
}

}  // namespace

std::vector<Vec3> frustum_section(const std::vector<Plane>& f, const Camera& c, double distance) {
    const Vec3 forward = glm::normalize(c.target - c.eye), right = glm::normalize(glm::cross(forward, c.up));
    const Vec3 up = glm::cross(right, forward), centre = c.eye + distance * forward;
    const double r = 1e3 * distance;  // wider than any frustum of less than 179.9°
    std::vector<Vec3> section = {centre - r * right - r * up, centre + r * right - r * up, centre + r * right + r * up, centre - r * right + r * up};
    const Tolerance tol{1e-12 * distance};
    for (std::size_t k = 0; k + 2 < f.size() && section.size() >= 3; ++k) {  // the side planes: all but near and far
        switch (classify(f[k], section, tol)) {
            case PolygonSide::back: section.clear(); break;
            case PolygonSide::spanning: section = split(f[k], section, tol).front; break;
            default: break;
        }
    }
    if (section.size() < 3) section.clear();
    return section;
}


Steps<PortalEvent, PortalRenderResult> portal_render(const CellModel* model, const CellBsp* bsp, const Pvs* pvs,
                                                      Camera cam, PortalRenderOptions options) {
    Render r{model, cam, pvs, options, cam.eye, glm::normalize(cam.target - cam.eye), {}, {}, 0, {}, {}, false};
    r.right = glm::normalize(glm::cross(r.forward, cam.up));
    r.up = glm::cross(r.right, r.forward);
    r.out.drawn.assign(model->polygons.size(), 0);
    if (cam.projection != Projection::perspective) throw InvalidInput("portal rendering needs a perspective camera");
    const std::vector<Plane> f = view_frustum(cam);
    // determine cell c of the viewpoint using the BSP tree
    const CellLocation where = locate_cell(*bsp, plan_point(r.eye));
    const bool in_a_room = where.cell && r.eye.y > 0 && r.eye.y < model->height;
    {
        const PortalEvent located = EyeLocated{in_a_room ? std::int32_t(*where.cell) : -1, where.path.path};
        co_yield located;
    }
    if (!in_a_room) {
        co_yield PortalRenderFinished{0, 0, 0, 0, 0};
        co_return r.out;
    }
    r.start = *where.cell;
    r.out.eye_cell = std::int32_t(r.start);
    // determine the PVS of cell c using the PVS matrix
    {
        const PortalEvent row = PvsRowRead{r.start, pvs->row(r.start)};
        co_yield row;
    }
    // f = the original view frustum; portal_render(c, f, PVS)
    auto top = render_cell(&r, r.start, f);
    for (const auto& e : top) co_yield e;
    std::uint32_t drawn = 0;
    for (std::uint8_t d : r.out.drawn) drawn += d;
    co_yield PortalRenderFinished{r.out.visits, drawn, r.out.culled_back_face, r.out.culled_frustum, r.out.portals_passed};
    co_return r.out;
}

}  // namespace hsr::algo
