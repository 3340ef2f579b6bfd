// SPDX-License-Identifier: MIT
#include "culling/occluders.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "core/events.h"
#include "core/overloaded.h"
#include "culling/view_frustum.h"

namespace hsr::algo {
namespace {

std::vector<Vec3> world_vertices(const ScenePolygon& p) {
    std::vector<Vec3> v;
    for (const auto& q : p.vertices) v.emplace_back(q);
    return v;
}

// Where the view comes from: the eye point of a perspective camera, or, for an orthographic one, the view
// direction along which every ray runs (the "eye" at infinity).
struct ViewOrigin {
    bool at_infinity;
    Vec3 eye, direction;  // direction: unit, from the eye into the scene
};

ViewOrigin view_origin(const Camera& c) {
    const Vec3 d = c.target - c.eye;
    return {c.projection == Projection::orthographic, c.eye, glm::length(d) > 0 ? glm::normalize(d) : Vec3(0, 0, -1)};
}

// Wholly beyond the near plane. What lies nearer is clipped away and hides nothing, so a polygon reaching in front
// of the near plane (or behind the eye, where a frustum through the eye turns inside out) is no occluder.
bool beyond_near_plane(const std::vector<Vec3>& poly, const Camera& c, const ViewOrigin& view) {
    return std::all_of(poly.begin(), poly.end(), [&](const Vec3& v) { return glm::dot(v - view.eye, view.direction) >= c.near; });
}

// The occlusion frustum of a convex polygon seen from the view's origin: inside when behind the polygon, within its
// edges. From an eye point the side planes pass through the eye; from a direction they run along it (a prism).
std::vector<Plane> occlusion_frustum(const std::vector<Vec3>& poly, const ViewOrigin& view, double eps) {
    std::vector<Plane> f;
    const Vec3 centre = centroid(poly);
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec3 &a = poly[i], &b = poly[(i + 1) % poly.size()];
        Plane p = view.at_infinity ? plane_through(glm::cross(b - a, view.direction), a) : plane_through(glm::cross(a - view.eye, b - view.eye), view.eye);
        if (p.distance(centre) < 0) p = {-p.n, -p.d};
        f.push_back(p);
    }
    Plane own;
    plane_of(poly, own);
    // the far side of the occluder is inside
    if (view.at_infinity ? glm::dot(own.n, view.direction) < 0 : own.distance(view.eye) > 0) own = {-own.n, -own.d};
    own.d -= eps;  // strictly behind it: the occluder (and what lies in its plane) is not culled by itself
    f.push_back(own);
    return f;
}

bool wholly_inside(const Aabb& box, const std::vector<Plane>& f) {
    return std::all_of(f.begin(), f.end(), [&](const Plane& p) { return box_side(box, p) > 0; });
}
bool wholly_outside(const Aabb& box, const std::vector<Plane>& f) {
    return std::any_of(f.begin(), f.end(), [&](const Plane& p) { return box_side(box, p) < 0; });
}

}  // namespace

double occluder_rank(const std::vector<Vec3>& poly, const Camera& camera) {
    const ViewOrigin view = view_origin(camera);
    if (!view.at_infinity) return occluder_rank(poly, view.eye);
    Plane p;  // seen along a direction: the area it covers on the screen, as large from any distance
    if (!plane_of(poly, p)) return 0;
    return std::max(0.0, -measure(poly) * glm::dot(p.n, view.direction));
}

double occluder_rank(const std::vector<Vec3>& poly, const Vec3& eye) {
    Plane p;
    if (!plane_of(poly, p)) return 0;
    const Vec3 v = centroid(poly) - eye;
    const double len2 = glm::dot(v, v);
    if (len2 == 0) return 0;
    return std::max(0.0, -measure(poly) * glm::dot(p.n, v / std::sqrt(len2)) / len2);
}

namespace {
// What occlusion culling says, each template once (its key is what another language's catalogue translates).
namespace say {
constexpr Saying chosen{"occluders.chosen", "Occluder: polygon #{polygon}, rank f = {rank}."};
constexpr Saying node_culled{"occluders.node_culled", "Node {node}: inside the frustum of occluder {occluder}, culled."};
constexpr Saying node_partly{"occluders.node_partly", "Node {node}: partly inside an occlusion frustum: its children are tested."};
constexpr Saying node_passed{"occluders.node_passed", "Node {node}: not inside any occlusion frustum, passed on."};
constexpr Saying primitive_culled{"occluders.primitive_culled", "Primitive #{primitive}: inside the frustum of occluder {occluder}, culled."};
constexpr Saying primitive_passed{"occluders.primitive_passed", "Primitive #{primitive}: not inside any occlusion frustum, passed on."};
constexpr Saying done{"occluders.done",
                      "Done: {occluders} {occluders?occluder|occluders}; {culled} {culled?primitive|primitives} culled, {passed} passed on."};
constexpr Saying all[] = {chosen, node_culled, node_partly, node_passed, primitive_culled, primitive_passed, done};
}  // namespace say

const Saying& tested_saying(const OcclusionTested& e) {
    const bool node = e.node >= 0;
    switch (e.outcome) {
        case OcclusionOutcome::occluded: return node ? say::node_culled : say::primitive_culled;
        case OcclusionOutcome::partly: return say::node_partly;  // only a node is split
        case OcclusionOutcome::visible: break;
    }
    return node ? say::node_passed : say::primitive_passed;
}
}  // namespace

std::span<const Saying> occluder_sayings() { return say::all; }

Phrase phrase(const OcclusionEvent& event) {
    const auto n = [](auto v) { return std::to_string(v); };
    return std::visit(overloaded{
                          [&](const OccluderChosen& e) { return Phrase(say::chosen, {{"polygon", n(e.polygon)}, {"rank", format_number(e.rank)}}); },
                          [&](const OcclusionTested& e) {
                              return Phrase(tested_saying(e), {{"node", n(e.node)}, {"primitive", n(e.primitive)}, {"occluder", n(e.occluder)}});
                          },
                          [&](const OcclusionFinished& e) {
                              return Phrase(say::done, {{"occluders", n(e.occluders)}, {"culled", n(e.culled)}, {"passed", n(e.passed)}});
                          },
                      },
                      event);
}

std::string describe(const OcclusionEvent& event) { return phrase(event).english(); }

Steps<OcclusionEvent, OcclusionCull> occlusion_cull(const Scene* scene, const Hierarchy* h, OcclusionOptions o) {
    OcclusionCull out;
    const std::size_t n = scene->polygons.size();
    out.kept = o.candidates.empty() ? std::vector<std::uint8_t>(n, 1) : o.candidates;
    const ViewOrigin view = view_origin(scene->camera);
    // Choose the occluders: the best ranked polygons
    std::vector<std::pair<double, std::uint32_t>> ranked;
    for (std::uint32_t i = 0; i < n; ++i)
        if (const auto poly = world_vertices(scene->polygons[i]); out.kept[i] && beyond_near_plane(poly, scene->camera, view))
            if (const double f = occluder_rank(poly, scene->camera); f > 0) ranked.push_back({f, i});
    std::sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    double extent = 1;
    for (const Aabb& b : h->boxes) extent = std::max({extent, std::abs(b.lo.x), std::abs(b.hi.x), std::abs(b.lo.y), std::abs(b.hi.y), std::abs(b.lo.z), std::abs(b.hi.z)});
    for (std::size_t k = 0; k < ranked.size() && k < o.max_occluders; ++k) {
        const auto poly = world_vertices(scene->polygons[ranked[k].second]);
        out.occluders.push_back({ranked[k].second, ranked[k].first, occlusion_frustum(poly, view, 1e-9 * extent)});
        co_yield OccluderChosen{ranked[k].second, ranked[k].first, measure(poly)};
    }
    // Cull top-down: a box wholly inside one occlusion frustum goes with its subtree
    const auto inside_one = [&](const Aabb& box) -> std::int32_t {
        for (std::size_t k = 0; k < out.occluders.size(); ++k)
            if (wholly_inside(box, out.occluders[k].frustum)) return std::int32_t(k);
        return -1;
    };
    const auto cull_below = [&](std::uint32_t top) {
        std::vector<std::uint32_t> stack{top};
        while (!stack.empty()) {
            const std::uint32_t m = stack.back();
            stack.pop_back();
            for (std::uint32_t p : h->nodes[m].primitives) out.culled += out.kept[p], out.kept[p] = 0;
            for (std::uint32_t c : h->nodes[m].children) stack.push_back(c);
        }
    };
    std::vector<std::uint32_t> stack;
    if (!h->nodes.empty() && !out.occluders.empty()) stack.push_back(0);
    while (!stack.empty()) {
        const std::uint32_t m = stack.back();
        stack.pop_back();
        const HierarchyNode& node = h->nodes[m];
        if (const std::int32_t k = inside_one(node.box); k >= 0) {
            cull_below(m);
            co_yield OcclusionTested{std::int32_t(m), -1, OcclusionOutcome::occluded, k};
            continue;
        }
        const bool touches = std::any_of(out.occluders.begin(), out.occluders.end(),
                                         [&](const Occluder& oc) { return !wholly_outside(node.box, oc.frustum); });
        co_yield OcclusionTested{std::int32_t(m), -1, touches ? OcclusionOutcome::partly : OcclusionOutcome::visible, -1};
        if (!touches) continue;  // outside every occlusion frustum: all of it is passed on
        for (std::uint32_t p : node.primitives) {
            if (!out.kept[p]) continue;
            const std::int32_t k = inside_one(h->boxes[p]);
            if (k >= 0) out.kept[p] = 0, ++out.culled;
            co_yield OcclusionTested{-1, std::int32_t(p), k >= 0 ? OcclusionOutcome::occluded : OcclusionOutcome::visible, k};
        }
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.push_back(*it);
    }
    std::uint32_t passed = 0;
    for (std::uint8_t k : out.kept) passed += k;
    co_yield OcclusionFinished{std::uint32_t(out.occluders.size()), out.culled, passed};
    co_return out;
}

}  // namespace hsr::algo
