// SPDX-License-Identifier: MIT
#include "scene/load_scene.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <set>

#include "bsp/bsp_events.h"
#include "core/events.h"
#include "core/numeric.h"
#include "core/plane.h"
#include "geometry/exact_collinear.h"
#include "scene/load_floor_plan.h"
#include "scene/load_terrain.h"
#include "scene/renderer_names.h"
#include "scene/load_mesh.h"

namespace hsr::algo {
namespace {

Color read_color(const TomlReader& r, const toml::table& t, const std::string& field) {
    const std::string s = r.text(t, "color", field, "#c8c8c8");
    auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    };
    bool ok = s.size() == 7 && s[0] == '#';
    for (std::size_t i = 1; ok && i < 7; ++i) ok = hex(s[i]) >= 0;
    if (!ok) r.fail(t.get("color"), join(field, "color"), "expected a colour \"#rrggbb\", got \"" + s + "\"");
    auto byte = [&](int i) { return std::uint8_t(hex(s[std::size_t(i)]) * 16 + hex(s[std::size_t(i + 1)])); };
    return {byte(1), byte(3), byte(5)};
}

Camera read_camera(const TomlReader& r, const toml::table* t) {
    Camera c;
    if (!t) return c;
    const std::string f = "camera";
    r.only_keys(*t, f, {"projection", "eye", "target", "up", "fov", "aspect", "near", "far", "box"});
    const std::string projection = r.text(*t, "projection", f, "perspective");
    if (projection == "perspective") c.projection = Projection::perspective;
    else if (projection == "orthographic") c.projection = Projection::orthographic;
    else r.fail(t->get("projection"), join(f, "projection"), "expected \"perspective\" or \"orthographic\"");
    auto vec3 = [&](std::string_view key, glm::dvec3 fallback) {
        const toml::node* n = t->get(key);
        return n ? glm::dvec3(r.vector(*n, join(f, key), 3, 3)) : fallback;
    };
    c.eye = vec3("eye", c.eye);
    c.target = vec3("target", c.target);
    c.up = vec3("up", c.up);
    c.fov_y = r.number(*t, "fov", f, c.fov_y);
    c.aspect = r.number(*t, "aspect", f, c.aspect);
    c.near = r.number(*t, "near", f, c.near);
    c.far = r.number(*t, "far", f, c.far);
    if (const toml::node* box = t->get("box")) {
        const glm::dvec4 b = r.vector(*box, join(f, "box"), 4, 4);
        for (int i = 0; i < 4; ++i) c.box[i] = b[i];
        if (!(c.box[0] < c.box[1] && c.box[2] < c.box[3]))
            r.fail(box, join(f, "box"), "expected left < right and bottom < top");
    }
    if (glm::length(c.target - c.eye) == 0) r.fail(t->get("target"), join(f, "target"), "target equals eye");
    if (glm::length(glm::cross(c.target - c.eye, c.up)) == 0)
        r.fail(t->get("up"), join(f, "up"), "up is parallel to the view direction (or zero)");
    if (c.projection == Projection::perspective && !(c.fov_y > 0 && c.fov_y < 180))
        r.fail(t->get("fov"), join(f, "fov"), "expected 0 < fov < 180 degrees");
    if (!(c.aspect > 0)) r.fail(t->get("aspect"), join(f, "aspect"), "expected aspect > 0");
    if (c.projection == Projection::perspective && !(c.near > 0))
        r.fail(t->get("near"), join(f, "near"), "expected near > 0 for a perspective camera");
    if (!(c.far > c.near)) r.fail(t->get("far"), join(f, "far"), "expected far > near");
    // Beyond 10^15 the perspective depth of everything rounds to the far plane's in every format, and the
    // projection's terms leave the doubles' range: the renderers would draw nothing while the painters draw all.
    if (c.projection == Projection::perspective && c.far / c.near > 1e15)
        r.fail(t->get("far"), join(f, "far"), "far / near is " + format_number(c.far / c.near) + "; at most 1e15");
    for (const auto& [key, p] : {std::pair{"eye", c.eye}, std::pair{"target", c.target}})
        if (std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > max_world_coordinate)
            r.fail(t->get(key), join(f, key), "world coordinates must lie within ±1e100");
    return c;
}


template <class Each>
void for_each_table(const TomlReader& r, const toml::table& root, std::string_view key, Each each) {
    const toml::array* a = r.array(root, key, "", false);
    if (!a) return;
    for (std::size_t i = 0; i < a->size(); ++i) {
        const std::string f = index(std::string(key), i);
        const toml::table* t = a->get(i)->as_table();
        if (!t) r.fail(a->get(i), f, "expected a table");
        each(*t, f);
    }
}

Expect read_expect(const TomlReader& r, const toml::table* t, const FloorPlan& plan) {
    Expect e;
    if (!t) return e;
    r.only_keys(*t, "expect", {"clip", "bsp", "cull", "pvs", "image", "rejects", "horizon"});
    const auto renderer = [&](const toml::table& c, const std::string& f, bool raycast_too) {
        std::string a = r.text(c, "algorithm", f);
        if (!is_renderer(a) || (!raycast_too && a == renderer_names.back()))
            r.fail(c.get("algorithm"), join(f, "algorithm"), "expected " + renderer_list(raycast_too));
        return a;
    };
    for_each_table(r, *t, "image", [&](const toml::table& c, const std::string& f0) {
        const std::string f = "expect." + f0;
        r.only_keys(c, f, {"algorithm", "format", "splitter", "size", "max_differing", "min_differing", "visible"});
        ExpectImage x{.algorithm = renderer(c, f, false), .line = int(c.source().begin.line)};
        x.format = r.text(c, "format", f, "int24");
        if (x.format != "int16" && x.format != "int24" && x.format != "int32" && x.format != "float32" &&
            x.format != "float32-reversed" && x.format != "linear24")
            r.fail(c.get("format"), join(f, "format"), "expected int16, int24, int32, float32, float32-reversed or linear24");
        x.splitter = r.text(c, "splitter", f, "first");
        if (!parse_splitter_rule(x.splitter))
            r.fail(c.get("splitter"), join(f, "splitter"), "expected " + std::string(splitter_rule_names));
        if (const toml::node* size = c.get("size")) {
            const glm::dvec4 v = r.vector(*size, join(f, "size"), 2, 2);
            if (!(v[0] >= 1 && v[0] <= 1024 && v[1] >= 1 && v[1] <= 1024 && v[0] == std::floor(v[0]) && v[1] == std::floor(v[1])))
                r.fail(size, join(f, "size"), "expected [width, height], whole numbers from 1 to 1024");
            x.width = int(v[0]), x.height = int(v[1]);
        }
        for (const char* key : {"max_differing", "min_differing"})
            if (c.contains(key)) {
                const double v = r.number(c, key, f);
                if (!(v >= 0 && v <= 1)) r.fail(c.get(key), join(f, key), "expected a share of pixels from 0 to 1");
                (std::string(key) == "max_differing" ? x.max_differing : x.min_differing) = v;
            }
        if (const toml::array* ids = r.array(c, "visible", f, false))
            for (std::size_t i = 0; i < ids->size(); ++i) {
                const auto id = ids->get(i)->value_exact<std::int64_t>();
                if (!id) r.fail(ids->get(i), index(join(f, "visible"), i), "expected a polygon id");
                x.visible.push_back(SceneId(*id));
            }
        e.image.push_back(std::move(x));
    });
    for_each_table(r, *t, "rejects", [&](const toml::table& c, const std::string& f0) {
        const std::string f = "expect." + f0;
        r.only_keys(c, f, {"algorithm", "message"});
        e.rejects.push_back({renderer(c, f, true), r.text(c, "message", f), int(c.source().begin.line)});
    });
    e.pvs = read_expect_pvs(r, r.table(*t, "pvs", "expect", false), plan);
    for_each_table(r, *t, "horizon", [&](const toml::table& c, const std::string& f0) {
        const std::string f = "expect." + f0;
        r.only_keys(c, f, {"columns", "visible"});
        ExpectHorizon x{.line = int(c.source().begin.line)};
        x.columns = int(std::clamp<std::int64_t>(r.integer(c, "columns", f, 20), 0, 1 << 20));
        if (x.columns < 1 || x.columns > 4096) r.fail(c.get("columns"), join(f, "columns"), "expected 1 to 4096 screen columns");
        if (c.contains("visible")) {
            const auto v = r.integer(c, "visible", f);
            if (v < 0) r.fail(c.get("visible"), join(f, "visible"), "expected a count of points, 0 or more");
            x.visible = std::uint64_t(v);
        }
        e.horizon.push_back(x);
    });
    for_each_table(r, *t, "cull", [&](const toml::table& c, const std::string& f0) {
        const std::string f = "expect." + f0;
        r.only_keys(c, f, {"test", "kept"});
        ExpectCull x{std::nullopt, {}, int(c.source().begin.line)};
        if (c.contains("test")) {
            x.test = r.text(c, "test", f);
            if (*x.test != "view_vector" && *x.test != "plane_equation" && *x.test != "screen_winding")
                r.fail(c.get("test"), join(f, "test"), "expected view_vector, plane_equation or screen_winding");
        }
        const toml::array* kept = r.array(c, "kept", f, true);
        for (std::size_t i = 0; i < kept->size(); ++i) {
            const auto id = kept->get(i)->value_exact<std::int64_t>();
            if (!id) r.fail(kept->get(i), index(join(f, "kept"), i), "expected a polygon id");
            x.kept.push_back(SceneId(*id));
        }
        e.cull.push_back(std::move(x));
    });
    for_each_table(r, *t, "bsp", [&](const toml::table& c, const std::string& f0) {
        const std::string f = "expect." + f0;
        r.only_keys(c, f, {"splitter", "eye", "order", "splits"});
        ExpectBsp x{r.text(c, "splitter", f, "first"), std::nullopt, std::nullopt, std::nullopt,
                    int(c.source().begin.line)};
        if (!parse_splitter_rule(x.splitter))
            r.fail(c.get("splitter"), join(f, "splitter"), "expected " + std::string(splitter_rule_names));
        if (const toml::node* eye = c.get("eye")) x.eye = glm::dvec3(r.vector(*eye, join(f, "eye"), 3, 3));
        if (const toml::array* order = r.array(c, "order", f, false)) {
            if (!x.eye) r.fail(&c, join(f, "eye"), "an expected order needs the eye it is seen from");
            x.order.emplace();
            for (std::size_t i = 0; i < order->size(); ++i) {
                const auto id = order->get(i)->value_exact<std::int64_t>();
                if (!id) r.fail(order->get(i), index(join(f, "order"), i), "expected a polygon id");
                x.order->push_back(SceneId(*id));
            }
        }
        if (c.contains("splits")) x.splits = int(r.integer(c, "splits", f));
        e.bsp.push_back(std::move(x));
    });
    for_each_table(r, *t, "clip", [&](const toml::table& c, const std::string& f0) {
        const std::string f = "expect." + f0;
        r.only_keys(c, f, {"id", "outcome", "vertices", "max_error"});
        ExpectClip x{SceneId(r.integer(c, "id", f)), r.text(c, "outcome", f), std::nullopt,
                     int(c.source().begin.line), std::nullopt};
        if (c.contains("max_error")) {
            x.max_error = r.number(c, "max_error", f);
            if (!(*x.max_error >= 0)) r.fail(c.get("max_error"), join(f, "max_error"), "expected a relative error ≥ 0");
        }
        if (x.outcome != "inside" && x.outcome != "clipped" && x.outcome != "rejected")
            r.fail(c.get("outcome"), join(f, "outcome"), "expected \"inside\", \"clipped\" or \"rejected\"");
        if (const toml::array* v = r.array(c, "vertices", f, false)) {
            x.vertices.emplace();
            for (std::size_t i = 0; i < v->size(); ++i)
                x.vertices->push_back(r.vector(*v->get(i), index(join(f, "vertices"), i), 4, 4));
        }
        e.clip.push_back(std::move(x));
    });
    return e;
}

}  // namespace

// Newell's normal is zero for a polygon with no area; "zero" relative to the polygon's size, so that collinear
// vertices given with rounding still count.
namespace {
// The polygon moved and scaled into a unit box (its size, the box's diagonal, returned): tests of shape then hold
// at any magnitude, where squares of coordinates near 1e154 would overflow.
std::vector<Vec3> unit_sized(const std::vector<glm::dvec4>& vertices, double& size) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const auto& x : vertices) lo = glm::min(lo, glm::dvec3(x)), hi = glm::max(hi, glm::dvec3(x));
    const glm::dvec3 extent = hi - lo;
    const double largest = std::max({extent.x, extent.y, extent.z});
    size = largest > 0 && std::isfinite(largest) ? glm::length(extent / largest) : 0;  // a diagonal of 1 … √3
    std::vector<Vec3> v;
    for (const auto& x : vertices) v.push_back(largest > 0 ? (glm::dvec3(x) - lo) / largest : glm::dvec3(0));
    return v;
}
}  // namespace

std::string not_planar(double b) {
    char s[160];
    std::snprintf(s, sizeof s, "the polygon is not planar: a vertex lies %.2g of its size off its plane (at most %.0e; split it into triangles)", b, max_bend);
    return s;
}

bool has_area(const std::vector<glm::dvec4>& vertices) {
    std::vector<Vec3> v;
    for (const auto& x : vertices) v.emplace_back(x);
    Plane plane;  // a sliver of any area is drawn; one too thin for a normal in doubles cannot be (never seen yet)
    return vertices.size() >= 3 && !collinear_exactly(v) && plane_of(v, plane);
}

std::string left_out_of_no_area(const std::string& where, std::size_t count, const std::string& what, const std::string& first) {
    return where + ": " + std::to_string(count) + " " + what + (count == 1 ? "" : "s") + " of no area left out (" + first +
           (count == 1 ? ")" : " first)");
}

double bend(const std::vector<glm::dvec4>& vertices) {
    double size = 0;
    const std::vector<Vec3> v = unit_sized(vertices, size);
    Plane plane;
    if (size == 0 || !plane_of(v, plane)) return 0;
    double farthest = 0;
    for (const Vec3& p : v) farthest = std::max(farthest, std::abs(plane.distance(p)));
    return farthest / size;
}

Scene read_scene(const TomlReader& r) {
    const toml::table& root = r.root();
    r.only_keys(root, "", {"name", "description", "coordinates", "camera", "points", "segments", "polygons", "meshes", "floor_plan", "terrain", "expect", "promise"});
    Scene s;
    s.source = r.path();
    s.name = r.text(root, "name", "", "untitled scene");
    s.promise = r.text(root, "promise", "", "");
    s.description = r.text(root, "description", "", "");
    const std::string coords = r.text(root, "coordinates", "", "world");
    if (coords == "world") s.coordinates = Coordinates::world;
    else if (coords == "clip") s.coordinates = Coordinates::clip;
    else r.fail(root.get("coordinates"), "coordinates", "expected \"world\" or \"clip\"");
    s.camera = read_camera(r, r.table(root, "camera", "", false));

    const std::size_t dims = s.coordinates == Coordinates::clip ? 4 : 3;
    std::set<SceneId> ids;
    auto read_id = [&](const toml::table& t, const std::string& f) {
        const auto id = r.integer(t, "id", f);
        if (id < 1 || id > 65535) r.fail(t.get("id"), join(f, "id"), "expected an id from 1 to 65535");
        if (!ids.insert(SceneId(id)).second)
            r.fail(t.get("id"), join(f, "id"), "id " + std::to_string(id) + " is used twice");
        return SceneId(id);
    };
    auto point = [&](const toml::node& n, const std::string& field) {
        const glm::dvec4 v = r.vector(n, field, dims, dims);
        if (s.coordinates == Coordinates::clip && !clippable(v))
            r.fail(&n, field, "clip-space coordinates must lie within ±1e307 (beyond it w − x can overflow)");
        if (s.coordinates == Coordinates::world && std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}) > max_world_coordinate)
            r.fail(&n, field, "world coordinates must lie within ±1e100 (beyond it plane tests can overflow)");
        return v;
    };
    auto vertex = [&](const toml::table& t, std::string_view key, const std::string& f) {
        const toml::node* n = t.get(key);
        if (!n) r.fail(&t, join(f, key), "missing; expected an array of " + std::to_string(dims) + " numbers");
        return point(*n, join(f, key));
    };
    for_each_table(r, root, "points", [&](const toml::table& t, const std::string& f) {
        r.only_keys(t, f, {"id", "color", "p"});
        s.points.push_back({read_id(t, f), read_color(r, t, f), vertex(t, "p", f)});
    });
    for_each_table(r, root, "segments", [&](const toml::table& t, const std::string& f) {
        r.only_keys(t, f, {"id", "color", "a", "b"});
        s.segments.push_back({read_id(t, f), read_color(r, t, f), vertex(t, "a", f), vertex(t, "b", f)});
    });
    std::size_t no_area = 0;
    std::string first_no_area, first_field;
    const toml::node* first_node = nullptr;
    for_each_table(r, root, "polygons", [&](const toml::table& t, const std::string& f) {
        r.only_keys(t, f, {"id", "color", "opacity", "vertices"});
        ScenePolygon p{read_id(t, f), read_color(r, t, f), {}};
        p.opacity = r.number(t, "opacity", f, 1.0);
        p.line = int(t.source().begin.line);
        if (!(p.opacity >= 0 && p.opacity <= 1)) r.fail(t.get("opacity"), join(f, "opacity"), "expected an opacity from 0 to 1");
        const toml::array* v = r.array(t, "vertices", f, true);
        for (std::size_t i = 0; i < v->size(); ++i)
            p.vertices.push_back(point(*v->get(i), index(join(f, "vertices"), i)));
        if (p.vertices.size() < 3)
            r.fail(t.get("vertices"), join(f, "vertices"), "a polygon needs at least 3 vertices");
        // a polygon of no area (its vertices on one line or at one point) covers no pixel: left out, and said
        if (s.coordinates == Coordinates::world && !has_area(p.vertices)) {
            if (no_area++ == 0) first_no_area = "line " + std::to_string(p.line), first_node = t.get("vertices"), first_field = join(f, "vertices");
            return;
        }
        if (s.coordinates == Coordinates::world && p.vertices.size() > 3 && bend(p.vertices) > max_bend)
            r.fail(t.get("vertices"), join(f, "vertices"), not_planar(bend(p.vertices)));
        s.polygons.push_back(std::move(p));
    });
    if (no_area > 0) s.notes.push_back(left_out_of_no_area(std::filesystem::path(r.path()).filename().string(), no_area, "polygon", first_no_area));
    read_meshes(r, s);
    if (no_area > 0 && s.polygons.empty())
        r.fail(first_node, first_field, "the polygon has no area (its vertices are on one line or at one point), nor has any other of the scene");
    for (std::size_t i = ids.size(); i < s.polygons.size(); ++i)  // mesh faces take ids too: none may be used twice
        if (!ids.insert(s.polygons[i].id).second)
            r.fail(root.get("meshes"), "meshes", "id " + std::to_string(s.polygons[i].id) + " is used twice");
    s.floor_plan = read_floor_plan(r, r.table(root, "floor_plan", "", false));
    if (s.floor_plan.eye) {  // the viewer of a floor plan stands in it: the camera follows
        const FloorPlan& plan = s.floor_plan;
        s.camera.eye = {plan.eye->x, plan.eye_height, -plan.eye->y};
        s.camera.target = {plan.look.x, plan.eye_height, -plan.look.y};
        s.camera.up = {0, 1, 0};
    }
    s.terrain = read_terrain(r, r.table(root, "terrain", "", false));
    s.expect = read_expect(r, r.table(root, "expect", "", false), s.floor_plan);
    for (const ExpectClip& x : s.expect.clip)
        if (!ids.contains(x.id))
            throw LoadError(r.path(), x.line, 1, "expect.clip.id",
                            "no primitive has id " + std::to_string(x.id));
    if (s.points.empty() && s.segments.empty() && s.polygons.empty() && s.floor_plan.cells.empty() && s.terrain.rows == 0)
        r.fail(nullptr, "", "the scene has nothing in it (no points, segments, polygons, meshes, floor plan or terrain): "
                            "an empty file, or one saved half-written?");
    return s;
}

Scene load_scene(const std::string& path) { return read_scene(TomlReader(path)); }
Scene load_scene_text(const std::string& path, std::string_view text) {
    return read_scene(TomlReader(path, text));
}

}  // namespace hsr::algo
