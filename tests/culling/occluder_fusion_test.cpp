// SPDX-License-Identifier: MIT
// Proxy occluders, Papaioannou's solid occluders and occluder fusion (culling/occluder_shapes.h):
// - the shapes: hulls hold their points, images and depths invert, a proxy's every point is hidden by its object
//   (a ray from the eye meets the object first), convex solids are found and open or dented ones are not;
// - fusion's union against a sampled reference (the area no cover takes, on a fine grid);
// - the machine on the scene built for it (assets/scenes/occluders_fusion.toml): one occluder at a time misses
//   the box behind the seam and the box behind the building's edge; fusion and the solid catch them;
// - every primitive culled is hidden, by an independent ray test (rays from the eye to points on it meet another
//   polygon first), and the pipeline's image with the stage is the image of every primitive, on the lesson's scene,
//   an orthographic camera, random cities and fields, and cases built to break it (a crack, an occluder in front of
//   the box and one behind it, a giant next to a tiny box, a box across the eye's plane).
#include <algorithm>
#include <random>

#include <glm/geometric.hpp>

#include "catch.h"
#include "analysis/lost_pixels.h"
#include "culling/occluder_shapes.h"
#include "culling/occluders.h"
#include "culling/pipeline.h"
#include "scene/generated_scenes.h"
#include "scene/load_scene.h"

using namespace hsr::algo;

namespace {

const Scene& fusion_scene() {
    static const Scene s = load_scene(HSR_SOURCE_DIR "/assets/scenes/occluders_fusion.toml");
    return s;
}

std::vector<Vec3> world(const ScenePolygon& p) {
    std::vector<Vec3> w;
    for (const auto& v : p.vertices) w.emplace_back(v);
    return w;
}

std::uint32_t index_of(const Scene& s, SceneId id) {
    for (std::uint32_t i = 0; i < s.polygons.size(); ++i)
        if (s.polygons[i].id == id) return i;
    FAIL("no polygon " << id);
    return 0;
}

// The reference: where the ray from `from` along `d` meets a convex polygon (t along d), written here on its own:
// the plane's intersection, then inside every edge (edges included).
std::optional<double> ray_meets(const Vec3& from, const Vec3& d, const std::vector<Vec3>& poly) {
    const Vec3 n = glm::cross(poly[1] - poly[0], poly[2] - poly[0]);
    const double den = glm::dot(n, d);
    if (den == 0) return std::nullopt;
    const double t = glm::dot(n, poly[0] - from) / den;
    if (!(t > 0)) return std::nullopt;
    const Vec3 p = from + d * t;
    const double scale = glm::length(n) * 1e-9 * (1 + glm::length(p));
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec3 &a = poly[i], &b = poly[(i + 1) % poly.size()];
        if (glm::dot(glm::cross(b - a, p - a), n) < -scale * glm::length(b - a)) return std::nullopt;
    }
    return t;
}

// Is the point hidden from the camera: does the ray from the eye (or along the view, orthographic) to it meet a
// polygon other than `self` strictly before it?
bool hidden(const Scene& s, const Vec3& point, std::uint32_t self) {
    const ViewPlane view = ViewPlane::of(s.camera);
    const Vec3 from = view.orthographic ? point - view.direction * (view.depth(point) + 1) : view.eye;
    const Vec3 d = point - from;  // t = 1 at the point
    for (std::uint32_t i = 0; i < s.polygons.size(); ++i) {
        if (i == self) continue;
        if (const auto t = ray_meets(from, d, world(s.polygons[i])); t && *t < 1 - 1e-9) return true;
    }
    return false;
}

// Points on a polygon: its corners pulled in by 1e-6 of the way to the centre, its centre, and random points inside.
std::vector<Vec3> samples(const std::vector<Vec3>& poly, std::mt19937& rng) {
    const Vec3 c = centroid(poly);
    std::vector<Vec3> out{c};
    for (const Vec3& v : poly) out.push_back(v + (c - v) * 1e-6);
    std::uniform_real_distribution<double> u(0, 1);
    for (int k = 0; k < 12; ++k) {
        const std::size_t i = std::size_t(u(rng) * double(poly.size())) % poly.size();
        const double a = u(rng), b = u(rng) * (1 - a);
        out.push_back(c + (poly[i] - c) * a + (poly[(i + 1) % poly.size()] - c) * b);
    }
    return out;
}

// Every primitive the stage culled is hidden at every sample (the pipeline's candidates: what reached the stage).
void check_culled_are_hidden(const Scene& s, const OcclusionCull& c, const std::vector<std::uint8_t>& candidates) {
    std::mt19937 rng(11);
    for (std::uint32_t i = 0; i < s.polygons.size(); ++i) {
        if (!candidates[i] || c.kept[i]) continue;
        for (const Vec3& p : samples(world(s.polygons[i]), rng)) {
            INFO("polygon #" << i << " (id " << s.polygons[i].id << ") at " << p.x << ", " << p.y << ", " << p.z);
            CHECK(hidden(s, p, i));
        }
    }
}

const StageReport& report(const PipelineResult& r, Stage st) {
    return *std::find_if(r.stages.begin(), r.stages.end(), [&](const StageReport& x) { return x.stage == st; });
}

struct Run {
    Hierarchy h;
    OcclusionCull cull;
    std::vector<OcclusionEvent> events;
};
Run run(const Scene& s, OccluderKind kind, bool fusion, std::vector<std::uint8_t> candidates = {}) {
    Run r;
    r.h = build_hierarchy(polygon_boxes(s), {}).run_to_end();
    auto steps = occlusion_cull(&s, &r.h, {.max_occluders = 8, .candidates = std::move(candidates), .kind = kind, .fusion = fusion});
    while (auto e = steps.next()) r.events.push_back(*e);
    r.cull = steps.result();
    return r;
}

// The test that culled a primitive: its own, or that of the node above it culled whole.
OcclusionTested culling_test(const Run& r, std::uint32_t primitive) {
    const auto holds = [&](std::uint32_t node) {
        std::vector<std::uint32_t> stack{node};
        while (!stack.empty()) {
            const std::uint32_t m = stack.back();
            stack.pop_back();
            const auto& n = r.h.nodes[m];
            if (std::find(n.primitives.begin(), n.primitives.end(), primitive) != n.primitives.end()) return true;
            stack.insert(stack.end(), n.children.begin(), n.children.end());
        }
        return false;
    };
    for (const auto& e : r.events)
        if (const auto* t = std::get_if<OcclusionTested>(&e); t && t->outcome == OcclusionOutcome::occluded)
            if (t->primitive == std::int32_t(primitive) || (t->node >= 0 && holds(std::uint32_t(t->node)))) return *t;
    FAIL("primitive #" << primitive << " was not culled");
    return {};
}

// The pipeline with the occluders stage confirms the machine: the same count left out, and its image is the image
// of every primitive. Returns the stage's candidates.
std::vector<std::uint8_t> check_pipeline(const Scene& s, OccluderKind kind, bool fusion, Viewport vp = {64, 48}) {
    const PipelineResult with = run_pipeline(s, {.stages = {Stage::back_face, Stage::frustum, Stage::occluders}, .viewport = vp, .occluders = kind, .fusion = fusion});
    const PipelineResult all = run_pipeline(s, {.stages = {}, .viewport = vp});
    CHECK(hsr::analysis::lost_front_pixels(s, with.frame, all.frame) == 0);
    CHECK(with.frame.image.ids == all.frame.image.ids);
    return report(with, Stage::occluders).candidates;
}

}  // namespace

TEST_CASE("the view plane: images and depths invert, a hull holds its points", "[culling][occluders][fusion]") {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (const Projection proj : {Projection::perspective, Projection::orthographic}) {
        Camera c;
        c.projection = proj, c.eye = {1, 2, 9}, c.target = {0.5, 0, 0}, c.up = {0.1, 1, 0}, c.near = 0.5;
        const ViewPlane v = ViewPlane::of(c);
        CHECK(glm::dot(v.right, v.up) == Approx(0).margin(1e-15));
        CHECK(glm::dot(glm::cross(v.right, v.up), v.direction) == Approx(-1));  // counter-clockwise images face the eye
        for (int k = 0; k < 100; ++k) {
            const Vec2 at{u(rng), u(rng)};
            const double z = 1 + 10 * (u(rng) + 1);
            const Vec3 p = v.point(at, z);
            CHECK(v.depth(p) == Approx(z));
            CHECK(glm::length(*v.image(p) - at) < 1e-12);
        }
        if (proj == Projection::perspective) CHECK_FALSE(v.image(c.eye - v.direction).has_value());  // behind the eye
    }
    for (int trial = 0; trial < 50; ++trial) {
        std::vector<Vec2> pts;
        for (int k = 0; k < 40; ++k) pts.push_back({u(rng), u(rng)});
        pts.push_back(pts[3]);  // a repeat
        const auto hull = convex_hull(pts);
        REQUIRE(hull.size() >= 3);
        for (std::size_t i = 0; i < hull.size(); ++i) {
            const Vec2 &a = hull[i], &b = hull[(i + 1) % hull.size()];
            for (const Vec2& p : pts) CHECK((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) >= -1e-15);  // all on the left
            CHECK(std::find(pts.begin(), pts.end(), a) != pts.end());
        }
    }
    CHECK(convex_hull({{0, 0}, {1, 1}, {2, 2}}).size() < 3);  // collinear: no area
}

TEST_CASE("a proxy lies behind its object on every projector, square to the view at its far end", "[culling][occluders][fusion]") {
    const Scene& s = fusion_scene();
    const auto solids = convex_solids(s);
    REQUIRE(solids.size() == 4);  // the three small boxes and the building; the two walls are no solid
    for (const auto& solid : solids) CHECK(solid.size() == 6);
    std::mt19937 rng(7);
    const ViewPlane view = ViewPlane::of(s.camera);
    for (const auto& solid : solids) {
        std::vector<Vec3> points;
        for (std::uint32_t i : solid) {
            const auto w = world(s.polygons[i]);
            points.insert(points.end(), w.begin(), w.end());
        }
        const auto proxy = proxy_of(points, view);
        REQUIRE(proxy.has_value());
        double far = 0;
        for (const Vec3& p : points) far = std::max(far, view.depth(p));
        for (const Vec3& q : *proxy) CHECK(view.depth(q) == Approx(far));
        // every point of the proxy is hidden by the solid: the ray from the eye meets one of its faces first (or there)
        for (const Vec3& q : samples(*proxy, rng)) {
            bool met = false;
            for (std::uint32_t i : solid)
                if (const auto t = ray_meets(view.eye, q - view.eye, world(s.polygons[i])); t && *t <= 1 + 1e-9) met = true;
            CHECK(met);
        }
    }
    // nearer than the near plane: no proxy (it would be clipped, and its image turns over behind the eye)
    std::vector<Vec3> across_eye{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 12}};
    CHECK_FALSE(proxy_of(across_eye, view).has_value());
}

TEST_CASE("convex solids: closed and convex, not open, not dented, not inside out", "[culling][occluders][fusion]") {
    Scene s;
    SceneId id = 1;
    add_box(s, {0, 0, 0}, {1, 1, 1}, {}, id);
    CHECK(convex_solids(s).size() == 1);
    Scene open = s;
    open.polygons.pop_back();
    CHECK(convex_solids(open).empty());
    Scene inside_out = s;
    for (auto& p : inside_out.polygons) std::reverse(p.vertices.begin(), p.vertices.end());
    CHECK(convex_solids(inside_out).empty());  // every face's plane has the others in front
    Scene dented = s;  // one corner pushed in: the faces meeting there bend inwards
    for (auto& p : dented.polygons)
        for (auto& v : p.vertices)
            if (v == glm::dvec4(1, 1, 1, 1)) v = {0.7, 0.7, 0.7, 1};
    CHECK(convex_solids(dented).empty());
    Scene city = city_scene({.triangles = 600});  // boxes of 12 triangles on a ground of 2
    const auto buildings = convex_solids(city);
    CHECK(buildings.size() * 12 + 2 == city.polygons.size());
    for (const auto& b : buildings) CHECK(b.size() == 12);
}

TEST_CASE("fusion's union against a sampled reference: the area no cover takes", "[culling][occluders][fusion]") {
    using P = std::vector<Vec2>;
    const P square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const P left{{-1, -1}, {0.5, -1}, {0.5, 2}, {-1, 2}}, right{{0.5, -1}, {2, -1}, {2, 2}, {0.5, 2}};
    SECTION("two halves sharing an edge cover it, each alone does not") {
        const std::vector<P> both{left, right};
        const Coverage c = covered_by_union(square, both, 1e-9);
        CHECK(c.covered);
        CHECK(c.used == 2);
        CHECK(c.area_left == 0);
        CHECK_FALSE(covered_by_union(square, std::vector<P>{left}, 1e-9).covered);
        CHECK(covered_by_union(square, std::vector<P>{left}, 1e-9).area_left == Approx(0.5));
    }
    SECTION("a crack wider than the gap stays open, a narrower one is closed") {
        P r1 = right;
        for (Vec2& p : r1)
            if (p.x == 0.5) p.x += 1e-6;
        CHECK_FALSE(covered_by_union(square, std::vector<P>{left, r1}, 1e-9).covered);
        CHECK(covered_by_union(square, std::vector<P>{left, r1}, 1e-9).area_left == Approx(1e-6).epsilon(1e-6));
        P r2 = right;
        for (Vec2& p : r2)
            if (p.x == 0.5) p.x += 1e-12;
        CHECK(covered_by_union(square, std::vector<P>{left, r2}, 1e-9).covered);
    }
    SECTION("a cover that misses is not counted as used") {
        const P far_away{{5, 5}, {6, 5}, {6, 6}, {5, 6}};
        const Coverage c = covered_by_union(square, std::vector<P>{far_away, left, right}, 1e-9);
        CHECK(c.covered);
        CHECK(c.used == 2);
    }
    SECTION("random convex covers: the area left is the sampled area no cover holds") {
        std::mt19937 rng(17);
        std::uniform_real_distribution<double> u(0, 1);
        const auto random_convex = [&](Vec2 centre, double r) {
            P pts;
            for (int k = 0; k < 7; ++k) pts.push_back(centre + Vec2(u(rng) - 0.5, u(rng) - 0.5) * (2 * r));
            return convex_hull(pts);
        };
        const auto inside = [](const P& poly, Vec2 p) {
            for (std::size_t i = 0; i < poly.size(); ++i) {
                const Vec2 &a = poly[i], &b = poly[(i + 1) % poly.size()];
                if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) < 0) return false;
            }
            return true;
        };
        int covered = 0;
        for (int trial = 0; trial < 60; ++trial) {
            const P image = random_convex({0.5, 0.5}, 0.4);
            std::vector<P> covers;
            for (int k = 0; k < 4; ++k) covers.push_back(random_convex({u(rng), u(rng)}, 0.3 + 0.4 * u(rng)));
            const Coverage c = covered_by_union(image, covers, 1e-9);
            const int n = 400;
            double left_sampled = 0, in_image = 0;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    const Vec2 p{(i + 0.5) / n, (j + 0.5) / n};
                    if (!inside(image, p)) continue;
                    in_image += 1;
                    if (std::none_of(covers.begin(), covers.end(), [&](const P& q) { return inside(q, p); })) left_sampled += 1;
                }
            const double cell = 1.0 / (double(n) * n);
            INFO("trial " << trial);
            CHECK(c.area_left == Approx(left_sampled * cell).margin(0.004));
            if (c.covered) {
                CHECK(left_sampled == 0);
                ++covered;
            }
            if (left_sampled > 4) CHECK_FALSE(c.covered);
            (void)in_image;
        }
        CHECK(covered > 3);  // the trials include covered images
    }
    CHECK_FALSE(covered_by_union(P{{0, 0}, {1, 0}, {2, 0}}, std::vector<P>{left}, 1e-9).covered);  // no area: no proof
}

TEST_CASE("the partial occlusion problem and its answers, on the lesson's scene", "[culling][occluders][fusion]") {
    const Scene& s = fusion_scene();
    const std::uint32_t seam = index_of(s, 15), behind_wall = index_of(s, 25), behind_edge = index_of(s, 45);  // front faces
    for (const OccluderKind kind : {OccluderKind::planar, OccluderKind::proxy, OccluderKind::solid})
        for (const bool fusion : {false, true}) {
            INFO(to_string(kind) << (fusion ? ", fused" : ""));
            const std::vector<std::uint8_t> candidates = check_pipeline(s, kind, fusion);
            const Run r = run(s, kind, fusion, candidates);
            check_culled_are_hidden(s, r.cull, candidates);
            CHECK(r.cull.kept[behind_wall] == 0);  // inside the left wall's frustum: every way
            // behind the seam: only fusion
            CHECK(r.cull.kept[seam] == (fusion ? 0 : 1));
            if (fusion) CHECK(culling_test(r, seam).fused == 2);
            // behind the building's edge: the solid, or fusion of its two faces
            CHECK(r.cull.kept[behind_edge] == (kind == OccluderKind::solid || fusion ? 0 : 1));
            if (kind == OccluderKind::solid) CHECK(culling_test(r, behind_edge).fused == 0);
            // the pipeline's count is the machine's
            const PipelineResult p = run_pipeline(s, {.stages = {Stage::back_face, Stage::frustum, Stage::occluders}, .viewport = {64, 48}, .occluders = kind, .fusion = fusion});
            CHECK(report(p, Stage::occluders).left_out == r.cull.culled);
            const auto& done = std::get<OcclusionFinished>(r.events.back());
            CHECK(done.culled == r.cull.culled);
            std::uint32_t fused = 0;
            for (const auto& e : r.events)
                if (const auto* t = std::get_if<OcclusionTested>(&e); t && t->primitive >= 0 && t->fused) ++fused;
            CHECK(done.fused >= fused);
        }
    // the solid stands for its six faces; the walls stay planar; a proxy of a wall facing the eye is the wall
    const Run solid = run(s, OccluderKind::solid, false);
    const auto chosen = [&](const Run& r) {
        std::vector<OccluderChosen> c;
        for (const auto& e : r.events)
            if (const auto* o = std::get_if<OccluderChosen>(&e)) c.push_back(*o);
        return c;
    };
    const auto solids = chosen(solid);
    CHECK(std::count_if(solids.begin(), solids.end(), [](const OccluderChosen& c) { return c.shape == OccluderKind::solid && c.faces == 6; }) >= 1);
    for (const OccluderChosen& c : chosen(run(s, OccluderKind::proxy, false)))
        if (c.polygon <= 1) CHECK(c.area == Approx(measure(world(s.polygons[c.polygon]))));
}

TEST_CASE("fusion and solids stay conservative on an orthographic camera, random cities and fields", "[culling][occluders][fusion]") {
    Scene ortho = fusion_scene();
    ortho.camera.projection = Projection::orthographic;
    ortho.camera.box[0] = -8, ortho.camera.box[1] = 8, ortho.camera.box[2] = -5, ortho.camera.box[3] = 7;
    ortho.camera.aspect = 16.0 / 12.0;
    for (const bool fusion : {false, true}) {
        const auto candidates = check_pipeline(ortho, OccluderKind::solid, fusion);
        const Run r = run(ortho, OccluderKind::solid, fusion, candidates);
        check_culled_are_hidden(ortho, r.cull, candidates);
        CHECK(r.cull.kept[index_of(ortho, 15)] == (fusion ? 0 : 1));  // the seam, seen along parallel rays
    }
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(-1, 1);
    int fused_somewhere = 0;
    for (int trial = 0; trial < 4; ++trial) {
        Scene s = trial % 2 ? field_scene({.triangles = 900, .seed = std::uint32_t(trial)}) : city_scene({.triangles = 900, .seed = std::uint32_t(trial)});
        s.camera.target += Vec3(u(rng), u(rng) * 0.3, u(rng)) * 3.0;
        s.camera.aspect = 4.0 / 3.0;
        INFO(s.name << ", trial " << trial);
        for (const OccluderKind kind : {OccluderKind::planar, OccluderKind::solid}) {
            const auto candidates = check_pipeline(s, kind, true, {96, 72});
            const Run one = run(s, kind, false, candidates), fused = run(s, kind, true, candidates);
            check_culled_are_hidden(s, fused.cull, candidates);
            for (std::size_t i = 0; i < s.polygons.size(); ++i) CHECK((one.cull.kept[i] == 0) <= (fused.cull.kept[i] == 0));  // fusion only adds
            fused_somewhere += fused.cull.culled > one.cull.culled;
        }
    }
    CHECK(fused_somewhere > 0);
}

TEST_CASE("fusion on cases built to break it", "[culling][occluders][fusion]") {
    const auto scene_of = [](double gap, double back_wall_z, double scale, double box_size) {
        Scene s;
        s.camera.eye = {0, 0, 10 * scale}, s.camera.target = {0, 0, 0}, s.camera.near = 0.1 * scale, s.camera.far = 100 * scale;
        s.camera.aspect = 1;
        SceneId id = 1;
        const auto wall = [&](double x0, double x1, double z) {
            s.polygons.push_back({id++, {}, {{x0, -4 * scale, z, 1}, {x1, -4 * scale, z, 1}, {x1, 4 * scale, z, 1}, {x0, 4 * scale, z, 1}}});
        };
        wall(-4 * scale, 0, 2 * scale);
        wall(gap * scale, 4 * scale, back_wall_z * scale);
        add_box(s, Vec3(-box_size, -box_size, -2 * scale - box_size), Vec3(box_size, box_size, -2 * scale + box_size), {}, id);
        return s;
    };
    const auto box_culled = [](const Scene& s) {  // every triangle of the box that reached the stage (after the walls)
        const auto candidates = check_pipeline(s, OccluderKind::planar, true);
        const Run r = run(s, OccluderKind::planar, true, candidates);
        check_culled_are_hidden(s, r.cull, candidates);
        bool all = true;
        for (std::size_t i = 2; i < s.polygons.size(); ++i) all = all && (!candidates[i] || !r.cull.kept[i]);
        return all;
    };
    CHECK(box_culled(scene_of(0, 2, 1, 0.3)));        // a seam: fused
    CHECK_FALSE(box_culled(scene_of(1e-3, 2, 1, 0.3)));  // a crack the eye sees through
    CHECK_FALSE(box_culled(scene_of(0, -5, 1, 0.3)));   // the right wall behind the box: it hides none of it
    CHECK(box_culled(scene_of(0, 1, 1, 0.3)));        // the right wall nearer still in front of the box
    CHECK(box_culled(scene_of(0, 2, 1e6, 1e-3)));     // giant walls, a tiny box
    CHECK(box_culled(scene_of(0, 2, 1e-6, 1e-10)));   // everything tiny
    {  // near the double limits: no crash, nothing visible culled (fusion may give up)
        const Scene huge = scene_of(0, 2, 1e150, 1e149);
        const Run r = run(huge, OccluderKind::solid, true);
        CHECK(r.cull.kept.size() == huge.polygons.size());
        CHECK(r.cull.kept[0] == 1);
        CHECK(r.cull.kept[1] == 1);
    }
    // a box reaching across the eye's plane (its image turns over): never culled, and no crash
    Scene across = scene_of(0, 2, 1, 0.3);
    SceneId next = 100;
    add_box(across, Vec3(-0.2, -0.2, 5), Vec3(0.2, 0.2, 12), {}, next);
    const Run r = run(across, OccluderKind::solid, true);
    for (std::size_t i = 14; i < across.polygons.size(); ++i) CHECK(r.cull.kept[i] == 1);  // after the walls and the first box's 12 triangles
}
