#include "portals/cell_model.h"

#include <algorithm>
#include <array>

#include <glm/geometric.hpp>

#include "core/numeric.h"

namespace hsr::algo {
namespace {

double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

// Okabe–Ito, a colour per cell; walls light, floors dark.
Color cell_color(std::size_t cell, bool floor) {
    static constexpr std::array<Color, 7> palette = {{{230, 159, 0}, {86, 180, 233}, {0, 158, 115}, {240, 228, 66},
                                                      {0, 114, 178}, {213, 94, 0}, {204, 121, 167}}};
    const Color c = palette[cell % palette.size()];
    const double k = floor ? 0.45 : 1.0;
    return {std::uint8_t(c.r * k), std::uint8_t(c.g * k), std::uint8_t(c.b * k)};
}

// A quad standing on the plan segment a→b from height y0 to y1, facing `inward` (a plan point in the cell).
std::vector<Vec3> wall_quad(Vec2 a, Vec2 b, double y0, double y1) {
    return {world_point(a, y0), world_point(b, y0), world_point(b, y1), world_point(a, y1)};
}

struct Opening {
    double t0, t1;  // along the edge, 0 at its start, 1 at its end
    double bottom, top;
};

}  // namespace

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
            Portal p{from, to, sp.from, sp.to, {}, {}, 0};
            Vec2 mean(0);
            for (const Vec2& v : m.cells[from].outline) mean += v / double(m.cells[from].outline.size());
            const Vec2 along = sp.to - sp.from, mid = (sp.from + sp.to) / 2.0;
            Vec2 through(along.y, -along.x);                            // across the opening
            if (glm::dot(through, mid - mean) < 0) through = -through;  // pointing out of `from`
            if (cross(through, p.left - p.right) < 0) std::swap(p.left, p.right);
            p.opening = wall_quad(p.right, p.left, sp.bottom, sp.top);
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
                const double t0 = std::min(t_of(p.left), t_of(p.right)), t1 = std::max(t_of(p.left), t_of(p.right));
                if (t1 < -eps || t0 > 1 + eps) continue;
                openings.push_back({std::max(t0, 0.0), std::min(t1, 1.0), p.opening[0].y, p.opening[2].y});
            }
            std::sort(openings.begin(), openings.end(), [](const Opening& x, const Opening& y) { return x.t0 < y.t0; });
            double t = 0;
            for (const Opening& o : openings) {
                if (o.t0 > t + eps) add(c, wall_quad(a + t * d, a + o.t0 * d, 0, plan.height), cell_color(c, false), next_id++, centre);
                const double ob = std::min(o.bottom, o.top), ot = std::max(o.bottom, o.top);
                if (ob > eps) add(c, wall_quad(a + o.t0 * d, a + o.t1 * d, 0, ob), cell_color(c, false), next_id++, centre);
                if (ot < plan.height - eps) add(c, wall_quad(a + o.t0 * d, a + o.t1 * d, ot, plan.height), cell_color(c, false), next_id++, centre);
                t = std::max(t, o.t1);
            }
            if (t < 1 - eps) add(c, wall_quad(a + t * d, b, 0, plan.height), cell_color(c, false), next_id++, centre);
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
