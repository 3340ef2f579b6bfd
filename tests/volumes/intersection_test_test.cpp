// SPDX-License-Identifier: MIT
// The hierarchical intersection test and its bounding volumes against independent references: k-DOPs hold their
// points, nest (6 ⊇ 14 ⊇ 26) and have the volume a grid of points inside their slabs says; each ray–volume test
// agrees with the same test in exact rationals (GMP) away from tangency; every answer of IntersectionTest equals a
// test of every polygon (no volume loses a primitive, even for rays aimed exactly at vertices and edges), and that in
// turn equals the exact rational ray–triangle test away from grazing; tighter volumes give fewer false alarms.
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <gmpxx.h>

#include "catch.h"
#include "core/numeric.h"
#include "culling/bounding_volume.h"
#include "scene/generated_scenes.h"
#include "volumes/intersection_test.h"

using namespace hsr::algo;

namespace {

Scene turned_boxes(int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-4, 4), thin(0.05, 0.3), len(0.8, 2.5), angle(0, 3.1);
    Scene s;
    SceneId id = 1;
    for (int b = 0; b < count; ++b) {
        const Vec3 c(pos(rng), pos(rng), pos(rng)), half(len(rng), b % 2 ? thin(rng) : len(rng), thin(rng));
        add_turned_box(s, c, half, glm::dmat3(glm::rotate(glm::dmat4(1), angle(rng), glm::normalize(Vec3(pos(rng), pos(rng), pos(rng)) + Vec3(0.1)))),
                       {}, id);
    }
    return s;
}

std::vector<Ray> random_rays(int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> g;
    std::uniform_real_distribution<double> pos(-4, 4);
    std::vector<Ray> out;
    for (int i = 0; i < count; ++i) {
        const Vec3 from = 14.0 * glm::normalize(Vec3(g(rng), g(rng), g(rng))), to(pos(rng), pos(rng), pos(rng));
        out.push_back({from, to - from});
    }
    return out;
}

// Rays aimed exactly at polygon vertices and at edge midpoints: the primitives on a volume's very boundary.
std::vector<Ray> rays_at_corners(const Scene& s, int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> g;
    std::vector<Ray> out;
    for (int i = 0; i < count; ++i) {
        const ScenePolygon& p = s.polygons[std::size_t(rng()) % s.polygons.size()];
        const std::size_t k = std::size_t(rng()) % p.vertices.size();
        const Vec3 a(p.vertices[k]), b(p.vertices[(k + 1) % p.vertices.size()]);
        const Vec3 target = i % 2 ? a : (a + b) / 2.0;
        const Vec3 from = 14.0 * glm::normalize(Vec3(g(rng), g(rng), g(rng)));
        out.push_back({from, target - from});
    }
    return out;
}

using Q = mpq_class;
struct QVec {
    Q x, y, z;
};
QVec q(const Vec3& v) { return {Q(v.x), Q(v.y), Q(v.z)}; }
Q dot(const QVec& a, const QVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
QVec sub(const QVec& a, const QVec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
QVec cross(const QVec& a, const QVec& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// The exact ray–triangle test (t > 0, barycentrics ≥ 0); `margin` gets the smallest barycentric, relative.
bool exact_hit(const Ray& r, const Vec3& a, const Vec3& b, const Vec3& c, double& margin) {
    const QVec o = q(r.origin), d = q(r.direction), A = q(a), e1 = sub(q(b), A), e2 = sub(q(c), A);
    const QVec p = cross(d, e2);
    const Q det = dot(e1, p);
    margin = 1;
    if (det == 0) return false;
    const QVec s = sub(o, A);
    const Q u = dot(s, p) / det;
    const QVec qq = cross(s, e1);
    const Q v = dot(d, qq) / det, t = dot(e2, qq) / det;
    margin = std::min({u.get_d(), v.get_d(), Q(1 - u - v).get_d()});
    return t > 0 && u >= 0 && v >= 0 && u + v <= 1;
}

// Every polygon (fans of triangles) of the scene, exactly; `grazing` when some hit or near miss is within 1e-9.
bool exact_any_hit(const Scene& s, const Ray& r, bool& grazing) {
    grazing = false;
    bool any = false;
    for (const ScenePolygon& p : s.polygons)
        for (std::size_t k = 1; k + 1 < p.vertices.size(); ++k) {
            double margin = 1;
            any = exact_hit(r, Vec3(p.vertices[0]), Vec3(p.vertices[k]), Vec3(p.vertices[k + 1]), margin) || any;
            grazing = grazing || std::abs(margin) < 1e-9;
        }
    return any;
}

bool brute_force(const BoundingModel& m, const Ray& ray) {
    const Ray r = unit_ray(ray);  // as the machine tests it
    for (std::size_t p = 0; p < m.polygons.size(); ++p)
        if (m.hittable[p] && hit(r, m.polygons[p], m.planes[p])) return true;
    return false;
}

std::vector<BoundingOptions> every_kind() {
    return {{.volume = VolumeKind::aabb},         {.volume = VolumeKind::sphere},       {.volume = VolumeKind::obb},
            {.volume = VolumeKind::kdop, .k = 6}, {.volume = VolumeKind::kdop, .k = 14}, {.volume = VolumeKind::kdop, .k = 18},
            {.volume = VolumeKind::kdop, .k = 26}, {.volume = VolumeKind::hulls}};
}

std::vector<Vec3> random_points(int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Vec3> pts;
    const glm::dmat3 turn(glm::rotate(glm::dmat4(1), 0.7, glm::normalize(Vec3(1, 2, 3))));
    for (int i = 0; i < count; ++i) pts.push_back(turn * Vec3(3 * u(rng), 0.5 * u(rng), 0.2 * u(rng)) + Vec3(1, -2, 0.5));
    return pts;
}

}  // namespace

TEST_CASE("k-DOPs hold their points, nest 6 ⊇ 14 ⊇ 26, and have the volume their slabs cut out", "[volumes]") {
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
        const std::vector<Vec3> pts = random_points(60, seed);
        double last = 1e300;
        for (const int k : {6, 14, 26}) {
            const KDop dop = kdop_of(pts, k);
            CHECK(dop.directions.size() == std::size_t(k / 2));
            for (const Vec3& p : pts)
                for (std::size_t i = 0; i < dop.directions.size(); ++i) {
                    CHECK(glm::dot(dop.directions[i], p) >= dop.lo[i]);
                    CHECK(glm::dot(dop.directions[i], p) <= dop.hi[i]);
                }
            const auto faces = kdop_faces(dop);
            const double volume = enclosed_volume(faces);
            CHECK(volume > 0);
            CHECK(volume <= last * (1 + 1e-12));  // each hull inside the one before
            last = volume;
            // every face vertex lies on the k-DOP's boundary: inside every slab, on at least one
            for (const auto& face : faces)
                for (const Vec3& v : face)
                    for (std::size_t i = 0; i < dop.directions.size(); ++i) {
                        const double s = glm::dot(dop.directions[i], v), tol = 1e-9 * (1 + std::abs(s));
                        CHECK((s >= dop.lo[i] - tol && s <= dop.hi[i] + tol));
                    }
            // the volume against a grid of points inside every slab (an independent count)
            const Aabb box = aabb_of(pts);
            const int n = 60;
            std::uint64_t inside = 0;
            for (int a = 0; a < n; ++a)
                for (int b = 0; b < n; ++b)
                    for (int c = 0; c < n; ++c) {
                        const Vec3 p = box.lo + box.size() * Vec3((a + 0.5) / n, (b + 0.5) / n, (c + 0.5) / n);
                        bool in = true;
                        for (std::size_t i = 0; i < dop.directions.size() && in; ++i) {
                            const double s = glm::dot(dop.directions[i], p);
                            in = s >= dop.lo[i] && s <= dop.hi[i];
                        }
                        inside += in;
                    }
            const double counted = double(inside) / (double(n) * n * n) * box.volume();
            CHECK(volume == Approx(counted).epsilon(0.05));
            if (k == 6) CHECK(volume == Approx(box.volume()).epsilon(1e-12));
        }
    }
}

TEST_CASE("ray–volume tests agree with the slab test in exact rationals", "[volumes]") {
    const std::vector<Vec3> pts = random_points(40, 7);
    const std::vector<Ray> rays = random_rays(400, 8);
    for (const int k : {6, 14, 18, 26}) {
        const KDop dop = kdop_of(pts, k);
        int decided = 0;
        for (const Ray& r : rays) {
            // exactly: the largest entering t against the smallest leaving t over the slabs, t ≥ 0
            Q enter(0), leave(0);
            bool bounded = false, empty = false;
            for (std::size_t i = 0; i < dop.directions.size() && !empty; ++i) {
                const QVec n = q(dop.directions[i]);
                const Q no = dot(n, q(r.origin)), nd = dot(n, q(r.direction)), lo(dop.lo[i]), hi(dop.hi[i]);
                if (nd == 0) {
                    empty = no < lo || no > hi;
                    continue;
                }
                Q a = (lo - no) / nd, b = (hi - no) / nd;
                if (a > b) std::swap(a, b);
                if (a > enter) enter = a;
                if (!bounded || b < leave) leave = b, bounded = true;
            }
            const bool exact = !empty && enter <= leave;
            const double gap = bounded ? std::abs(Q(leave - enter).get_d()) / (1 + std::abs(leave.get_d())) : 1;
            if (gap < 1e-9) continue;  // grazing an edge of the k-DOP: rounding may decide either way
            ++decided;
            CHECK(ray_through(dop, r.origin, r.direction).has_value() == exact);
        }
        CHECK(decided > 300);
    }
}

TEST_CASE("IntersectionTest answers as a test of every polygon, for every kind of volume, and that is the exact answer", "[volumes]") {
    const Scene s = turned_boxes(20, 3);
    std::vector<Ray> rays = random_rays(300, 4);
    const std::vector<Ray> at_corners = rays_at_corners(s, 200, 5);
    rays.insert(rays.end(), at_corners.begin(), at_corners.end());
    const BoundingModel all = bounding_model(s, {});
    std::vector<std::uint8_t> truth;
    int exact_checked = 0;
    for (const Ray& r : rays) {
        truth.push_back(brute_force(all, r));
        bool grazing = false;
        const bool exact = exact_any_hit(s, r, grazing);
        if (grazing) continue;
        ++exact_checked;
        CHECK(bool(truth.back()) == exact);
    }
    CHECK(exact_checked > 250);
    for (const BoundingOptions& o : every_kind()) {
        const IntersectionResult result = intersection_test(s, rays, {.bounding = o}).run_to_end();
        REQUIRE(result.hits.size() == rays.size());
        for (std::size_t r = 0; r < rays.size(); ++r) {
            INFO("volume " << to_string(o.volume) << " k " << o.k << ", ray " << r);
            REQUIRE(result.hits[r] == truth[r]);
        }
        CHECK(result.false_alarms <= result.volume_tests);
    }
}

TEST_CASE("tighter volumes give fewer false alarms on the same hierarchy, and hulls end where the 26-DOP does", "[volumes]") {
    const Scene s = turned_boxes(30, 11);
    const std::vector<Ray> rays = random_rays(500, 12);
    const auto run = [&](BoundingOptions o) { return intersection_test(s, rays, {.bounding = o}).run_to_end(); };
    const IntersectionResult aabb = run({.volume = VolumeKind::aabb}), six = run({.volume = VolumeKind::kdop, .k = 6}),
                             fourteen = run({.volume = VolumeKind::kdop, .k = 14}), twenty_six = run({.volume = VolumeKind::kdop, .k = 26}),
                             hulls = run({.volume = VolumeKind::hulls});
    CHECK(six.false_alarms == aabb.false_alarms);  // the 6-DOP is the axis box
    CHECK(six.primitive_tests == aabb.primitive_tests);
    CHECK(fourteen.false_alarms <= six.false_alarms);
    CHECK(twenty_six.false_alarms <= fourteen.false_alarms);
    CHECK(twenty_six.false_alarms < aabb.false_alarms);  // turned boxes: the diagonals cut real void away
    CHECK(hulls.false_alarms == twenty_six.false_alarms);
    CHECK(hulls.primitive_tests == twenty_six.primitive_tests);
    CHECK(hulls.volume_tests > twenty_six.volume_tests);  // the outer hulls are tested first
    // every node's volume holds its subtree's vertices (a volume that did not could lose a primitive)
    for (const BoundingOptions& o : every_kind()) {
        const BoundingModel m = bounding_model(s, o);
        for (std::size_t node = 0; node < m.tree.nodes.size(); ++node) {
            const NodeVolume& v = m.volumes[node];
            std::vector<std::uint32_t> stack = {std::uint32_t(node)};
            while (!stack.empty()) {
                const HierarchyNode& n = m.tree.nodes[stack.back()];
                stack.pop_back();
                stack.insert(stack.end(), n.children.begin(), n.children.end());
                for (const std::uint32_t p : n.primitives)
                    for (const Vec3& x : m.polygons[p]) {
                        if (o.volume == VolumeKind::aabb) CHECK(v.box.contains(aabb_of(std::vector<Vec3>{x})));
                        if (o.volume == VolumeKind::sphere) CHECK(glm::distance(x, v.sphere.centre) <= v.sphere.radius);
                        if (o.volume == VolumeKind::obb)
                            for (int a = 0; a < 3; ++a) CHECK(std::abs(glm::dot(x - v.obb.centre, v.obb.axes[std::size_t(a)])) <= v.obb.half[a]);
                        for (const KDop& d : v.dops)
                            for (std::size_t i = 0; i < d.directions.size(); ++i)
                                CHECK((glm::dot(d.directions[i], x) >= d.lo[i] && glm::dot(d.directions[i], x) <= d.hi[i]));
                    }
            }
        }
    }
}

TEST_CASE("IntersectionTest follows the notes: the bottom level tests its primitives, the || skips what is not needed", "[volumes]") {
    const Scene s = turned_boxes(12, 21);
    const std::vector<Ray> rays = random_rays(40, 22);
    auto steps = intersection_test(s, rays, {.bounding = {.volume = VolumeKind::kdop, .k = 14}});
    std::vector<IntersectionEvent> events;
    for (const auto& e : steps) events.push_back(e);
    const BoundingModel m = bounding_model(s, {.volume = VolumeKind::kdop, .k = 14});
    int skipped = 0, alarms = 0, entered = 0, answered = 0;
    for (const auto& e : events) {
        if (const auto* x = std::get_if<ModelEntered>(&e)) {
            ++entered;
            CHECK(x->bottom == m.tree.nodes[x->node].children.empty());
        }
        if (const auto* x = std::get_if<PrimitiveHitTested>(&e)) CHECK(m.tree.nodes[x->node].children.empty());  // only at the bottom
        if (const auto* x = std::get_if<VolumeTested>(&e)) CHECK_FALSE(m.tree.nodes[x->node].children.empty());  // never at the bottom
        if (std::holds_alternative<ComponentSkipped>(e)) ++skipped;
        if (const auto* x = std::get_if<ModelAnswered>(&e)) ++answered, alarms += x->false_alarm;
    }
    CHECK(entered == answered);  // every call returns
    CHECK(skipped > 0);          // some ray hit in an early component
    CHECK(std::uint64_t(alarms) == steps.result().false_alarms);
}

TEST_CASE("IntersectionTest on extreme rays and polygons, the step bound, and what it refuses", "[volumes]") {
    Scene s = turned_boxes(6, 31);
    ScenePolygon sliver{900, {}, {{0, 0, 0, 1}, {1e-300, 0, 0, 1}, {0, 1e-300, 0, 1}}};  // an area doubles cannot hold
    ScenePolygon giant{901, {}, {{-1e6, -1e6, -20, 1}, {1e6, -1e6, -20, 1}, {0, 1e6, -20, 1}}};
    ScenePolygon segment{902, {}, {{0, 0, 0, 1}, {1, 1, 1, 1}}};
    s.polygons.insert(s.polygons.end(), {sliver, giant, segment});
    const std::vector<Ray> rays = {{{0, 0, 10}, {0, 0, -1}},     {{0, 0, 10}, {0, 0, -1e-300}}, {{0, 0, 10}, {1e300, 0, -1e300}},
                                   {{5, 5, 5}, {1e-3, 2e-3, -1}}, {{0, 0, -30}, {0, 0, -1}}};
    const BoundingModel all = bounding_model(s, {});
    for (const BoundingOptions& o : every_kind()) {
        const IntersectionResult r = intersection_test(s, rays, {.bounding = o}).run_to_end();
        for (std::size_t k = 0; k < rays.size(); ++k) CHECK(bool(r.hits[k]) == brute_force(all, rays[k]));
        CHECK_FALSE(r.hits[4]);  // beyond the giant, looking away
    }
    const IntersectionResult bounded = intersection_test(s, rays, {.max_steps = 3}).run_to_end();
    CHECK(bounded.bounded);
    CHECK(bounded.volume_tests + bounded.primitive_tests == 3);

    CHECK_THROWS_AS(intersection_test(s, {}).run_to_end(), InvalidInput);
    CHECK_THROWS_AS(intersection_test(Scene{}, rays).run_to_end(), InvalidInput);
    CHECK_THROWS_AS(intersection_test(s, rays, {.bounding = {.volume = VolumeKind::kdop, .k = 7}}).run_to_end(), InvalidInput);
    CHECK_THROWS_AS(intersection_test(s, rays, {.bounding = {.max_primitives = 0}}).run_to_end(), InvalidInput);
    CHECK_THROWS_AS(intersection_test(s, {{{0, 0, 0}, {0, 0, 0}}}).run_to_end(), InvalidInput);
}
