// SPDX-License-Identifier: MIT
#include "scene/load_floor_plan.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <glm/geometric.hpp>

#include "geometry/polygon_2d.h"

namespace hsr::algo {
namespace {

// Do the edges go round once? A star (a pentagram) turns the same way at every corner too, but goes round twice.
bool winds_once(const std::vector<glm::dvec2>& p) {
    double turned = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const glm::dvec2 a = p[i], b = p[(i + 1) % p.size()], c = p[(i + 2) % p.size()];
        const glm::dvec2 u = b - a, w = c - b;
        turned += std::atan2(cross(u, w), u.x * w.x + u.y * w.y);
    }
    return std::abs(turned) < 3 * M_PI;
}

// Points in order round a convex polygon with area (either way round; no three in a row).
bool convex_with_area(const std::vector<glm::dvec2>& p, double eps) {
    if (p.size() < 3 || !winds_once(p)) return false;
    double sign = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const glm::dvec2 a = p[i], b = p[(i + 1) % p.size()], c = p[(i + 2) % p.size()];
        const double turn = cross(b - a, c - b);
        if (std::abs(turn) <= eps) return false;
        if (sign != 0 && (turn > 0) != (sign > 0)) return false;
        sign = turn;
    }
    return std::abs(twice_signed_area(p)) > eps;
}

glm::dvec2 point2(const TomlReader& r, const toml::node& n, const std::string& field) {
    const toml::array* a = n.as_array();
    if (!a || a->size() != 2) r.fail(&n, field, "expected [x, y] (2 numbers)");
    glm::dvec2 p;
    for (int i = 0; i < 2; ++i) {
        const auto v = a->get(std::size_t(i))->value<double>();
        if (!v || !std::isfinite(*v)) r.fail(a->get(std::size_t(i)), field, "expected [x, y] (2 finite numbers)");
        p[i] = *v;
    }
    return p;
}


// Distance from p to the segment ab.
double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 d = b - a;
    const double t = std::clamp(glm::dot(p - a, d) / glm::dot(d, d), 0.0, 1.0);
    return glm::length(p - (a + t * d));
}

// Is the segment pq on one edge of the outline (both ends within eps of the same edge)?
bool on_an_edge(const std::vector<glm::dvec2>& outline, glm::dvec2 p, glm::dvec2 q, double eps) {
    for (std::size_t i = 0; i < outline.size(); ++i) {
        const glm::dvec2 a = outline[i], b = outline[(i + 1) % outline.size()];
        if (distance_to_segment(p, a, b) <= eps && distance_to_segment(q, a, b) <= eps) return true;
    }
    return false;
}

// Do two convex outlines overlap with area (more than touching)? Separating axes: the edges' normals.
bool overlap(const std::vector<glm::dvec2>& a, const std::vector<glm::dvec2>& b, double eps) {
    for (const auto* poly : {&a, &b})
        for (std::size_t i = 0; i < poly->size(); ++i) {
            const glm::dvec2 e = (*poly)[(i + 1) % poly->size()] - (*poly)[i], axis(-e.y, e.x);
            double a0 = 1e300, a1 = -1e300, b0 = 1e300, b1 = -1e300;
            for (const auto& p : a) a0 = std::min(a0, glm::dot(p, axis)), a1 = std::max(a1, glm::dot(p, axis));
            for (const auto& p : b) b0 = std::min(b0, glm::dot(p, axis)), b1 = std::max(b1, glm::dot(p, axis));
            if (a1 <= b0 + eps * glm::length(axis) || b1 <= a0 + eps * glm::length(axis)) return false;
        }
    return true;
}

SceneCell read_cell(const TomlReader& r, const toml::table& t, const std::string& f) {
    r.only_keys(t, f, {"name", "rect", "outline"});
    SceneCell c{r.text(t, "name", f), {}, int(t.source().begin.line)};
    if (c.name.empty()) r.fail(t.get("name"), join(f, "name"), "a cell needs a name");
    if (const toml::node* rect = t.get("rect")) {
        const toml::array* a = rect->as_array();
        double v[4];
        for (std::size_t i = 0; i < 4; ++i) {
            const auto x = a && a->size() == 4 ? a->get(i)->value<double>() : std::nullopt;
            if (!x || !std::isfinite(*x)) r.fail(rect, join(f, "rect"), "expected [x0, y0, x1, y1] (4 finite numbers)");
            v[i] = *x;
        }
        if (!(v[0] < v[2] && v[1] < v[3])) r.fail(rect, join(f, "rect"), "expected x0 < x1 and y0 < y1");
        c.outline = {{v[0], v[1]}, {v[2], v[1]}, {v[2], v[3]}, {v[0], v[3]}};
    } else {
        const toml::array* a = r.array(t, "outline", f, true);
        for (std::size_t i = 0; i < a->size(); ++i) c.outline.push_back(point2(r, *a->get(i), index(join(f, "outline"), i)));
        if (c.outline.size() < 3) r.fail(t.get("outline"), join(f, "outline"), "a cell needs at least 3 corners");
        if (twice_signed_area(c.outline) < 0) std::reverse(c.outline.begin(), c.outline.end());  // counter-clockwise, whichever way it was written
        for (std::size_t i = 0; i < c.outline.size(); ++i) {
            const glm::dvec2 a0 = c.outline[i], a1 = c.outline[(i + 1) % c.outline.size()], a2 = c.outline[(i + 2) % c.outline.size()];
            if (cross(a1 - a0, a2 - a1) <= 0)
                r.fail(t.get("outline"), join(f, "outline"), "the cell is not convex (or has a straight angle) at corner " + std::to_string((i + 1) % c.outline.size()));
        }
        if (!winds_once(c.outline))
            r.fail(t.get("outline"), join(f, "outline"), "the cell's outline crosses itself (it goes round more than once, like a star)");
    }
    return c;
}

}  // namespace

FloorPlan read_floor_plan(const TomlReader& r, const toml::table* t) {
    FloorPlan plan;
    if (!t) return plan;
    const std::string f = "floor_plan";
    r.only_keys(*t, f, {"height", "cells", "portals", "eye", "look", "eye_height"});
    plan.height = r.number(*t, "height", f, plan.height);
    if (!(plan.height > 0)) r.fail(t->get("height"), join(f, "height"), "expected a height > 0");
    plan.eye_height = r.number(*t, "eye_height", f, plan.eye_height);
    if (!(plan.eye_height > 0 && plan.eye_height < plan.height))
        r.fail(t->get("eye_height"), join(f, "eye_height"), "expected 0 < eye_height < height");
    if (const toml::node* eye = t->get("eye")) plan.eye = point2(r, *eye, join(f, "eye"));
    if (const toml::node* look = t->get("look")) plan.look = point2(r, *look, join(f, "look"));
    if (plan.eye && glm::length(plan.look - *plan.eye) == 0) r.fail(t->get("look"), join(f, "look"), "look equals eye");

    std::set<std::string> names;
    double extent = 0;
    const toml::array* cells = r.array(*t, "cells", f, true);
    for (std::size_t i = 0; i < cells->size(); ++i) {
        const std::string fi = index(join(f, "cells"), i);
        const toml::table* ct = cells->get(i)->as_table();
        if (!ct) r.fail(cells->get(i), fi, "expected a table");
        SceneCell c = read_cell(r, *ct, fi);
        if (!names.insert(c.name).second) r.fail(ct->get("name"), join(fi, "name"), "cell \"" + c.name + "\" is named twice");
        for (const auto& p : c.outline) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
        plan.cells.push_back(std::move(c));
    }
    const double eps = 1e-9 * std::max(extent, 1.0);
    // Cells may share walls but not floor: sorted by their left edge, each is compared with those it could overlap
    std::vector<std::size_t> by_x(plan.cells.size());
    for (std::size_t i = 0; i < by_x.size(); ++i) by_x[i] = i;
    const auto x_range = [&](std::size_t i) {
        double lo = 1e300, hi = -1e300;
        for (const auto& p : plan.cells[i].outline) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
        return std::pair{lo, hi};
    };
    std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) { return x_range(a).first < x_range(b).first; });
    for (std::size_t i = 0; i < by_x.size(); ++i)
        for (std::size_t j = i + 1; j < by_x.size() && x_range(by_x[j]).first < x_range(by_x[i]).second; ++j)
            if (overlap(plan.cells[by_x[i]].outline, plan.cells[by_x[j]].outline, eps)) {
                const SceneCell& later = plan.cells[std::max(by_x[i], by_x[j])];
                throw LoadError(r.path(), later.line, 1, index(join(f, "cells"), std::max(by_x[i], by_x[j])),
                                "cells \"" + plan.cells[by_x[i]].name + "\" and \"" + plan.cells[by_x[j]].name + "\" overlap");
            }
    const auto cell_named = [&](const std::string& name) {
        return std::find_if(plan.cells.begin(), plan.cells.end(), [&](const SceneCell& c) { return c.name == name; });
    };
    if (const toml::array* portals = r.array(*t, "portals", f, false))
        for (std::size_t i = 0; i < portals->size(); ++i) {
            const std::string fi = index(join(f, "portals"), i);
            const toml::table* pt = portals->get(i)->as_table();
            if (!pt) r.fail(portals->get(i), fi, "expected a table");
            r.only_keys(*pt, fi, {"between", "from", "to", "bottom", "top", "shape"});
            const std::vector<std::string> between = r.strings(*pt, "between", fi);
            if (between.size() != 2 || between[0] == between[1])
                r.fail(pt->get("between"), join(fi, "between"), "expected the names of two different cells");
            ScenePortal p{{between[0], between[1]}, {}, {}, 0, 0, {}, int(pt->source().begin.line)};
            for (const std::string& name : between)
                if (cell_named(name) == plan.cells.end()) r.fail(pt->get("between"), join(fi, "between"), "no cell is named \"" + name + "\"");
            if (!pt->get("from") || !pt->get("to")) r.fail(pt, fi, "a portal needs from = [x, y] and to = [x, y]");
            p.from = point2(r, *pt->get("from"), join(fi, "from"));
            p.to = point2(r, *pt->get("to"), join(fi, "to"));
            if (glm::length(p.to - p.from) <= eps) r.fail(pt->get("to"), join(fi, "to"), "the opening has no width");
            for (const std::string& name : between)
                if (!on_an_edge(cell_named(name)->outline, p.from, p.to, eps))
                    r.fail(pt->get("from"), join(fi, "from"), "the opening is not on a wall of cell \"" + name + "\"");
            p.bottom = r.number(*pt, "bottom", fi, 0.0);
            p.top = r.number(*pt, "top", fi, plan.height);
            if (!(p.bottom >= 0 && p.bottom < p.top && p.top <= plan.height))
                r.fail(pt->get("top"), join(fi, "top"), "expected 0 <= bottom < top <= the rooms' height");
            if (const toml::array* shape = r.array(*pt, "shape", fi, false)) {
                if (pt->contains("bottom") || pt->contains("top"))
                    r.fail(pt->get("shape"), join(fi, "shape"), "give either shape or bottom and top, not both");
                for (std::size_t k = 0; k < shape->size(); ++k) {
                    const glm::dvec2 q = point2(r, *shape->get(k), index(join(fi, "shape"), k));
                    if (!(q.x >= 0 && q.x <= 1 && q.y >= 0 && q.y <= plan.height))
                        r.fail(shape->get(k), index(join(fi, "shape"), k), "expected [s, h] with 0 <= s <= 1 (from `from` to `to`) and 0 <= h <= the rooms' height");
                    p.shape.push_back(q);
                }
                if (!convex_with_area(p.shape, eps))
                    r.fail(pt->get("shape"), join(fi, "shape"), "expected 3 or more points making a convex polygon with area, in order");
            }
            plan.portals.push_back(std::move(p));
        }
    return plan;
}

std::vector<ExpectPvs> read_expect_pvs(const TomlReader& r, const toml::table* t, const FloorPlan& plan) {
    std::vector<ExpectPvs> out;
    if (!t) return out;
    const auto known = [&](const std::string& name) {
        return std::any_of(plan.cells.begin(), plan.cells.end(), [&](const SceneCell& c) { return c.name == name; });
    };
    for (const auto& [key, node] : *t) {
        const std::string name(key.str()), f = "expect.pvs." + name;
        if (!known(name)) r.fail(&node, f, "no cell is named \"" + name + "\"");
        ExpectPvs x{name, r.strings(*t, key.str(), "expect.pvs"), int(node.source().begin.line)};
        for (const std::string& v : x.visible)
            if (!known(v)) r.fail(&node, f, "no cell is named \"" + v + "\"");
        out.push_back(std::move(x));
    }
    return out;
}

}  // namespace hsr::algo
