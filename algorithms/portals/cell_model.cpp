// SPDX-License-Identifier: MIT
#include "portals/cell_model.h"

#include <algorithm>
#include <array>

#include <glm/geometric.hpp>

#include "core/numeric.h"
#include "geometry/polygon_2d.h"
#include "core/okabe_ito.h"

namespace hsr::algo {
namespace {


// Okabe–Ito, a colour per cell; walls light, floors dark.
Color cell_color(std::size_t cell, bool floor) {
    const Color c = okabe_ito::as<Color>(okabe_ito::series[cell % okabe_ito::series.size()]);
    const double k = floor ? 0.45 : 1.0;
    return {std::uint8_t(c.r * k), std::uint8_t(c.g * k), std::uint8_t(c.b * k)};
}

// A quad standing on the plan segment a→b from height y0 to y1, facing `inward` (a plan point in the cell).
std::vector<Vec3> wall_quad(Vec2 a, Vec2 b, double y0, double y1) {
    return {world_point(a, y0), world_point(b, y0), world_point(b, y1), world_point(a, y1)};
}

// An opening in one wall: its outline as (t, h), t along the wall from 0 at its start to 1 at its end.
struct Opening {
    double t0, t1;  // its extent along the wall
    std::vector<glm::dvec2> outline;
};

// The wall between plan points a and b with heights lo and hi at each end: a quad, or a triangle where lo = hi.
std::vector<Vec3> wall_piece(Vec2 a, Vec2 b, double lo_a, double lo_b, double hi_a, double hi_b, double eps) {
    std::vector<Vec3> v{world_point(a, lo_a), world_point(b, lo_b)};
    if (hi_b - lo_b > eps) v.push_back(world_point(b, hi_b));
    if (hi_a - lo_a > eps) v.push_back(world_point(a, hi_a));
    return v;
}

}  // namespace

bool in_opening(const Portal& p, const Vec3& x, double margin) {
    for (std::size_t i = 0; i < p.opening.size(); ++i) {
        const Vec3& a = p.opening[i];
        const Vec3 e = p.opening[(i + 1) % p.opening.size()] - a;
        if (glm::dot(glm::cross(e, x - a), p.plane.n) < margin * glm::length(e)) return false;
    }
    return true;
}

bool inside(const std::vector<Vec2>& outline, Vec2 p, double eps) {
    for (std::size_t i = 0; i < outline.size(); ++i) {
        const Vec2 a = outline[i], b = outline[(i + 1) % outline.size()];
        if (cross(b - a, p - a) < -eps * glm::length(b - a)) return false;
    }
    return true;
}

std::optional<std::uint32_t> cell_at(const CellModel& m, Vec2 p) {
    for (std::uint32_t c = 0; c < m.cells.size(); ++c)
        if (inside(m.cells[c].outline, p, m.tol.epsilon)) return c;
    return std::nullopt;
}

CellModel cell_model(const Scene& scene) {
    const FloorPlan& plan = scene.floor_plan;
    if (plan.cells.empty()) throw InvalidInput("the scene has no [floor_plan] cells");
    CellModel m;
    m.height = plan.height;
    m.camera = scene.camera;
    double extent = plan.height;
    for (const SceneCell& c : plan.cells)
        for (const Vec2& p : c.outline) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
    m.tol = Tolerance::for_extent(extent);
    const double eps = m.tol.epsilon;
    for (const SceneCell& c : plan.cells) m.cells.push_back({c.name, c.outline, {}, {}});
    const auto index_of = [&](const std::string& name) {
        return std::uint32_t(std::find_if(plan.cells.begin(), plan.cells.end(), [&](const SceneCell& c) { return c.name == name; }) - plan.cells.begin());
    };
    // Portals, once each way: seen going from `from` into `to`, the left end is on the left
    for (const ScenePortal& sp : plan.portals) {
        const std::uint32_t a = index_of(sp.between[0]), b = index_of(sp.between[1]);
        for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
            // the opening's shape as (s, h), s from 0 at sp.from to 1 at sp.to: the rectangle unless one is given
            const std::vector<Vec2> shape = !sp.shape.empty() ? sp.shape
                                                             : std::vector<Vec2>{{0, sp.bottom}, {1, sp.bottom}, {1, sp.top}, {0, sp.top}};
            double s0 = 1, s1 = 0;
            for (const Vec2& q : shape) s0 = std::min(s0, q.x), s1 = std::max(s1, q.x);
            const Vec2 along = sp.to - sp.from, mid = (sp.from + sp.to) / 2.0;
            Portal p{from, to, sp.from + s0 * along, sp.from + s1 * along, {}, {}, 0};
            Vec2 mean(0);
            for (const Vec2& v : m.cells[from].outline) mean += v / double(m.cells[from].outline.size());
            Vec2 through(along.y, -along.x);                            // across the opening
            if (glm::dot(through, mid - mean) < 0) through = -through;  // pointing out of `from`
            if (cross(through, p.left - p.right) < 0) std::swap(p.left, p.right);
            for (const Vec2& q : shape) p.opening.push_back(world_point(sp.from + q.x * along, q.y));
            plane_of(p.opening, p.plane);
            if (glm::dot(p.plane.n, world_point(mid + through, 0) - world_point(mid, 0)) < 0) {
                std::reverse(p.opening.begin(), p.opening.end());
                plane_of(p.opening, p.plane);
            }
            m.cells[from].portals.push_back(std::uint32_t(m.portals.size()));
            m.portals.push_back(std::move(p));
        }
        m.portals[m.portals.size() - 1].twin = std::uint32_t(m.portals.size() - 2);
        m.portals[m.portals.size() - 2].twin = std::uint32_t(m.portals.size() - 1);
    }
    // Walls with their openings cut out, and floors; then the scene's objects, each in the cell it stands in
    SceneId next_id = 1;
    for (const ScenePolygon& p : scene.polygons) next_id = std::max(next_id, p.id + 1);
    const auto add = [&](std::uint32_t cell, std::vector<Vec3> v, Color color, SceneId id, const Vec3& toward) {
        CellPolygon poly{id, color, cell, std::move(v), {}};
        if (!plane_of(poly.vertices, poly.plane)) return;
        if (poly.plane.distance(toward) < 0) {
            std::reverse(poly.vertices.begin(), poly.vertices.end());
            plane_of(poly.vertices, poly.plane);
        }
        m.cells[cell].polygons.push_back(std::uint32_t(m.polygons.size()));
        m.polygons.push_back(std::move(poly));
    };
    for (std::uint32_t c = 0; c < m.cells.size(); ++c) {
        const auto& outline = m.cells[c].outline;
        Vec2 mean(0);
        for (const Vec2& v : outline) mean += v / double(outline.size());
        const Vec3 centre = world_point(mean, plan.height / 2);
        for (std::size_t i = 0; i < outline.size(); ++i) {
            const Vec2 a = outline[i], b = outline[(i + 1) % outline.size()], d = b - a;
            std::vector<Opening> openings;
            for (std::uint32_t k : m.cells[c].portals) {
                const Portal& p = m.portals[k];
                const auto t_of = [&](Vec2 q) { return glm::dot(q - a, d) / glm::dot(d, d); };
                if (std::abs(cross(d, p.left - a)) > eps * glm::length(d) || std::abs(cross(d, p.right - a)) > eps * glm::length(d)) continue;
                Opening o{1e300, -1e300, {}};
                for (const Vec3& v : p.opening) {
                    o.outline.push_back({std::clamp(t_of(plan_point(v)), 0.0, 1.0), v.y});
                    o.t0 = std::min(o.t0, o.outline.back().x), o.t1 = std::max(o.t1, o.outline.back().x);
                }
                if (o.t1 < -eps || o.t0 > 1 + eps) continue;
                openings.push_back(std::move(o));
            }
            std::sort(openings.begin(), openings.end(), [](const Opening& x, const Opening& y) { return x.t0 < y.t0; });
            double t = 0;
            const double te = eps / glm::length(d);  // eps as a share of the wall
            for (const Opening& o : openings) {
                if (o.t0 > t + te) add(c, wall_quad(a + t * d, a + o.t0 * d, 0, plan.height), cell_color(c, false), next_id++, centre);
                // Below each edge of the opening's lower side, wall down to the floor; above each edge of its upper
                // side, wall up to the ceiling: convex pieces, however the opening is shaped
                glm::dvec2 mean_th(0);
                for (const glm::dvec2& q : o.outline) mean_th += q / double(o.outline.size());
                for (std::size_t k = 0; k < o.outline.size(); ++k) {
                    glm::dvec2 e0 = o.outline[k], e1 = o.outline[(k + 1) % o.outline.size()];
                    if (std::abs(e1.x - e0.x) <= te) continue;  // an upright side: no wall above or below it
                    if (e0.x > e1.x) std::swap(e0, e1);
                    const double h_at_mean = e0.y + (e1.y - e0.y) * (mean_th.x - e0.x) / (e1.x - e0.x);
                    const Vec2 pa = a + e0.x * d, pb = a + e1.x * d;
                    if (mean_th.y > h_at_mean) {  // the opening is above this edge: wall from the floor up to it
                        if (std::max(e0.y, e1.y) > eps) add(c, wall_piece(pa, pb, 0, 0, e0.y, e1.y, eps), cell_color(c, false), next_id++, centre);
                    } else if (std::min(e0.y, e1.y) < plan.height - eps) {
                        add(c, wall_piece(pa, pb, e0.y, e1.y, plan.height, plan.height, eps), cell_color(c, false), next_id++, centre);
                    }
                }
                t = std::max(t, o.t1);
            }
            if (t < 1 - te) add(c, wall_quad(a + t * d, b, 0, plan.height), cell_color(c, false), next_id++, centre);
        }
        std::vector<Vec3> floor;
        for (const Vec2& v : outline) floor.push_back(world_point(v, 0));
        add(c, std::move(floor), cell_color(c, true), next_id++, centre);
    }
    for (const ScenePolygon& p : scene.polygons) {
        std::vector<Vec3> v;
        for (std::size_t k = 0; k < p.vertices.size(); ++k) {
            require_finite(p.vertices[k], "polygon " + std::to_string(p.id) + " vertex " + std::to_string(k));
            v.emplace_back(p.vertices[k]);
        }
        const auto cell = cell_at(m, plan_point(centroid(v)));
        if (!cell) throw InvalidInput("polygon " + std::to_string(p.id) + " stands in no cell");
        CellPolygon poly{p.id, p.color, *cell, std::move(v), {}};
        if (!plane_of(poly.vertices, poly.plane)) throw InvalidInput("polygon " + std::to_string(p.id) + " has no area");
        m.cells[*cell].polygons.push_back(std::uint32_t(m.polygons.size()));
        m.polygons.push_back(std::move(poly));
    }
    // ids go past 65535 only for plans of thousands of rooms; the 16-bit id image refuses those, nothing else does
    return m;
}

Scene model_scene(const CellModel& m) {
    Scene s;
    s.camera = m.camera;
    for (const CellPolygon& p : m.polygons) {
        ScenePolygon sp{p.id, p.color, {}};
        for (const Vec3& v : p.vertices) sp.vertices.emplace_back(v, 1.0);
        s.polygons.push_back(std::move(sp));
    }
    return s;
}

}  // namespace hsr::algo
