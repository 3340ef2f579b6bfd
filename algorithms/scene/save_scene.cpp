// SPDX-License-Identifier: MIT
#include "scene/save_scene.h"

#include <cstdio>
#include <sstream>

#include <toml++/toml.h>

namespace hsr::algo {
namespace {

toml::array vec(const glm::dvec4& v, bool four) {
    toml::array a{v.x, v.y, v.z};
    if (four) a.push_back(v.w);
    return a;
}
toml::array vec3(const glm::dvec3& v) { return toml::array{v.x, v.y, v.z}; }
toml::array vec2(const glm::dvec2& v) { return toml::array{v.x, v.y}; }
std::string hex(Color c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
    return buf;
}

}  // namespace

std::string scene_toml(const Scene& s) {
    const bool clip = s.coordinates == Coordinates::clip;
    toml::table root;
    root.insert("name", s.name);
    root.insert("description", s.description);
    if (!s.promise.empty()) root.insert("promise", s.promise);
    root.insert("coordinates", clip ? "clip" : "world");
    const Camera& c = s.camera;
    toml::table camera{{"projection", c.projection == Projection::perspective ? "perspective" : "orthographic"},
                       {"eye", vec3(c.eye)}, {"target", vec3(c.target)}, {"up", vec3(c.up)}, {"fov", c.fov_y},
                       {"aspect", c.aspect}, {"near", c.near}, {"far", c.far},
                       {"box", toml::array{c.box[0], c.box[1], c.box[2], c.box[3]}}};
    root.insert("camera", std::move(camera));
    toml::array points, segments, polygons;
    for (const auto& p : s.points) points.push_back(toml::table{{"id", p.id}, {"color", hex(p.color)}, {"p", vec(p.p, clip)}});
    for (const auto& g : s.segments)
        segments.push_back(toml::table{{"id", g.id}, {"color", hex(g.color)}, {"a", vec(g.a, clip)}, {"b", vec(g.b, clip)}});
    for (const auto& p : s.polygons) {
        toml::array v;
        for (const auto& q : p.vertices) v.push_back(vec(q, clip));
        toml::table t{{"id", p.id}, {"color", hex(p.color)}, {"vertices", std::move(v)}};
        if (p.opacity != 1) t.insert("opacity", p.opacity);
        polygons.push_back(std::move(t));
    }
    if (!points.empty()) root.insert("points", std::move(points));
    if (!segments.empty()) root.insert("segments", std::move(segments));
    if (!polygons.empty()) root.insert("polygons", std::move(polygons));
    const FloorPlan& f = s.floor_plan;
    if (!f.cells.empty()) {
        toml::table plan{{"height", f.height}, {"look", vec2(f.look)}, {"eye_height", f.eye_height}};
        if (f.eye) plan.insert("eye", vec2(*f.eye));
        toml::array cells, portals;
        for (const auto& cell : f.cells) {
            toml::array outline;
            for (const auto& p : cell.outline) outline.push_back(vec2(p));
            cells.push_back(toml::table{{"name", cell.name}, {"outline", std::move(outline)}});
        }
        for (const auto& p : f.portals) {
            toml::table portal{{"between", toml::array{p.between[0], p.between[1]}}, {"from", vec2(p.from)}, {"to", vec2(p.to)}};
            if (p.shape.empty()) {
                portal.insert("bottom", p.bottom);
                if (p.top > 0) portal.insert("top", p.top);  // 0, as a plan made in code may say: up to the ceiling
            } else {
                toml::array shape;
                for (const auto& q : p.shape) shape.push_back(vec2(q));
                portal.insert("shape", std::move(shape));
            }
            portals.push_back(std::move(portal));
        }
        plan.insert("cells", std::move(cells));
        if (!portals.empty()) plan.insert("portals", std::move(portals));
        root.insert("floor_plan", std::move(plan));
    }
    if (const Terrain& t = s.terrain; t.rows > 0) {
        toml::array heights;
        for (int j = 0; j < t.rows; ++j) {
            toml::array row;
            for (int i = 0; i < t.columns; ++i) row.push_back(t.height(i, j));
            heights.push_back(std::move(row));
        }
        root.insert("terrain", toml::table{{"spacing", toml::array{t.dx, t.dz}}, {"elevation", t.elevation}, {"heights", std::move(heights)}});
    }
    std::ostringstream out;
    out << "# Saved by hsrviz\n" << root << "\n";
    return out.str();
}

}  // namespace hsr::algo
