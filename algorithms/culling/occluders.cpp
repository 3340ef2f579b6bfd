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

// Wholly beyond the near plane. What lies nearer is clipped away and hides nothing, so a polygon reaching in front
// of the near plane (or behind the eye, where a frustum through the eye turns inside out) is no occluder.
bool beyond_near_plane(const std::vector<Vec3>& poly, const ViewPlane& view) {
    return std::all_of(poly.begin(), poly.end(), [&](const Vec3& v) { return view.depth(v) >= view.near; });
}

// The occlusion frustum of a convex polygon seen from the view's origin: inside when behind the polygon, within its
// edges. From an eye point the side planes pass through the eye; from a direction they run along it (a prism).
std::vector<Plane> occlusion_frustum(const std::vector<Vec3>& poly, const ViewPlane& view, double eps) {
    std::vector<Plane> f;
    const Vec3 centre = centroid(poly);
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec3 &a = poly[i], &b = poly[(i + 1) % poly.size()];
        Plane p = view.orthographic ? plane_through(glm::cross(b - a, view.direction), a) : plane_through(glm::cross(a - view.eye, b - view.eye), view.eye);
        if (p.distance(centre) < 0) p = {-p.n, -p.d};
        f.push_back(p);
    }
    Plane own;
    plane_of(poly, own);
    // the far side of the occluder is inside
    if (view.orthographic ? glm::dot(own.n, view.direction) < 0 : own.distance(view.eye) > 0) own = {-own.n, -own.d};
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
    const ViewPlane view = ViewPlane::of(camera);
    if (!view.orthographic) return occluder_rank(poly, view.eye);
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
constexpr Saying chosen_proxy{"occluders.chosen_proxy",
                              "Occluder: the proxy of polygon #{polygon}, square to the view at its far end, rank f = {rank}."};
constexpr Saying chosen_solid{"occluders.chosen_solid",
                              "Occluder: the solid of {faces} faces with polygon #{polygon}, as the proxy of its volume, rank f = {rank}."};
constexpr Saying node_fused{"occluders.node_fused",
                            "Node {node}: in no single frustum, but behind {fused} occluders whose images together cover it: culled (fusion)."};
constexpr Saying primitive_fused{"occluders.primitive_fused",
                                 "Primitive #{primitive}: in no single frustum, but behind {fused} occluders whose images together cover it: culled (fusion)."};
constexpr Saying node_culled{"occluders.node_culled", "Node {node}: inside the frustum of occluder {occluder}, culled."};
constexpr Saying node_partly{"occluders.node_partly", "Node {node}: partly inside an occlusion frustum: its children are tested."};
constexpr Saying node_passed{"occluders.node_passed", "Node {node}: not inside any occlusion frustum, passed on."};
constexpr Saying primitive_culled{"occluders.primitive_culled", "Primitive #{primitive}: inside the frustum of occluder {occluder}, culled."};
constexpr Saying primitive_passed{"occluders.primitive_passed", "Primitive #{primitive}: not inside any occlusion frustum, passed on."};
constexpr Saying done{"occluders.done",
                      "Done: {occluders} {occluders?occluder|occluders}; {culled} {culled?primitive|primitives} culled, {passed} passed on."};
constexpr Saying done_fused{"occluders.done_fused",
                            "Done: {occluders} {occluders?occluder|occluders}; {culled} {culled?primitive|primitives} culled, {fused} of them by fusion; {passed} passed on."};
constexpr Saying all[] = {chosen, chosen_proxy, chosen_solid, node_culled, node_partly, node_passed, node_fused, primitive_culled, primitive_passed, primitive_fused, done, done_fused};
}  // namespace say

const Saying& tested_saying(const OcclusionTested& e) {
    const bool node = e.node >= 0;
    switch (e.outcome) {
        case OcclusionOutcome::occluded:
            if (e.fused) return node ? say::node_fused : say::primitive_fused;
            return node ? say::node_culled : say::primitive_culled;
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
                          [&](const OccluderChosen& e) {
                              const Saying& s = e.shape == OccluderKind::solid ? say::chosen_solid : e.shape == OccluderKind::proxy ? say::chosen_proxy : say::chosen;
                              return Phrase(s, {{"polygon", n(e.polygon)}, {"rank", format_number(e.rank)}, {"faces", n(e.faces)}});
                          },
                          [&](const OcclusionTested& e) {
                              return Phrase(tested_saying(e),
                                            {{"node", n(e.node)}, {"primitive", n(e.primitive)}, {"occluder", n(e.occluder)}, {"fused", n(e.fused)}});
                          },
                          [&](const OcclusionFinished& e) {
                              return Phrase(e.fused ? say::done_fused : say::done,
                                            {{"occluders", n(e.occluders)}, {"culled", n(e.culled)}, {"passed", n(e.passed)}, {"fused", n(e.fused)}});
                          },
                      },
                      event);
}

std::string describe(const OcclusionEvent& event) { return phrase(event).english(); }

namespace {

struct Candidate {
    double rank;
    std::uint32_t polygon;
    OccluderKind shape;
    std::vector<std::uint32_t> faces;
    std::vector<Vec3> outline;
};

// The occluders the options ask for, before ranking: each candidate polygon as it is or as its proxy, and with
// solid occluders each closed convex object whose faces facing the eye all reached this stage as one proxy.
std::vector<Candidate> occluder_candidates(const Scene& scene, const std::vector<std::uint8_t>& kept, const ViewPlane& view, OccluderKind kind,
                                          const std::vector<std::vector<std::uint32_t>>* solids) {
    std::vector<Candidate> out;
    std::vector<std::uint8_t> in_solid(scene.polygons.size(), 0);
    std::vector<std::vector<std::uint32_t>> found;
    if (kind == OccluderKind::solid && !solids) found = convex_solids(scene), solids = &found;
    if (kind == OccluderKind::solid)
        for (const std::vector<std::uint32_t>& solid : *solids) {
            std::vector<Vec3> points;
            bool seen = true;  // every face that faces the eye reached this stage (none culled before as too small)
            for (std::uint32_t i : solid) {
                const auto poly = world_vertices(scene.polygons[i]);
                points.insert(points.end(), poly.begin(), poly.end());
                if (occluder_rank(poly, scene.camera) > 0 && !kept[i]) seen = false;
            }
            if (!seen) continue;
            if (auto proxy = proxy_of(points, view))
                if (const double f = occluder_rank(*proxy, scene.camera); f > 0) {
                    for (std::uint32_t i : solid) in_solid[i] = 1;  // its faces are not occluders of their own
                    out.push_back({f, solid.front(), OccluderKind::solid, solid, std::move(*proxy)});
                }
        }
    for (std::uint32_t i = 0; i < scene.polygons.size(); ++i) {
        if (!kept[i] || in_solid[i]) continue;
        auto poly = world_vertices(scene.polygons[i]);
        if (!beyond_near_plane(poly, view) || !(occluder_rank(poly, scene.camera) > 0)) continue;  // facing away: hides nothing
        if (kind != OccluderKind::proxy) {  // planar, and the polygons of no solid beside the solids
            const double f = occluder_rank(poly, scene.camera);
            out.push_back({f, i, OccluderKind::planar, {i}, std::move(poly)});
        } else if (auto proxy = proxy_of(poly, view)) {
            if (const double f = occluder_rank(*proxy, scene.camera); f > 0) out.push_back({f, i, OccluderKind::proxy, {i}, std::move(*proxy)});
        }
    }
    // the best first; equal ranks by polygon, so the choice does not depend on the sort
    std::sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) { return a.rank > b.rank || (a.rank == b.rank && a.polygon < b.polygon); });
    return out;
}

std::vector<Vec2> image_of(const std::vector<Vec3>& outline, const ViewPlane& view) {
    std::vector<Vec2> at;
    for (const Vec3& v : outline)
        if (const auto p = view.image(v)) at.push_back(*p);
    return at.size() == outline.size() ? convex_hull(std::move(at)) : std::vector<Vec2>{};
}

// Fusion: the box's image against the images of the occluders it lies wholly behind. A gap narrower than 1e-9 of
// the image's size is closed (two occluders sharing an edge meet there up to rounding).
std::uint32_t fused_cover(const Aabb& box, const std::vector<Occluder>& occluders, const ViewPlane& view) {
    const auto image = box_image(box, view);
    if (!image || image->size() < 3) return 0;
    Vec2 lo(1e308), hi(-1e308);
    for (const Vec2& p : *image) lo = glm::min(lo, p), hi = glm::max(hi, p);
    std::vector<std::vector<Vec2>> covers;
    for (const Occluder& o : occluders) {
        if (o.image.size() < 3 || box_side(box, o.frustum.back()) <= 0) continue;  // not wholly behind it
        Vec2 olo(1e308), ohi(-1e308);
        for (const Vec2& p : o.image) olo = glm::min(olo, p), ohi = glm::max(ohi, p);
        if (olo.x > hi.x || olo.y > hi.y || ohi.x < lo.x || ohi.y < lo.y) continue;
        covers.push_back(o.image);
    }
    if (covers.size() < 2) return 0;  // one alone was tested in 3D already
    const double size = std::max({glm::length(hi - lo), std::abs(lo.x), std::abs(lo.y), std::abs(hi.x), std::abs(hi.y)});
    if (!(size < 1e100)) return 0;  // areas of images this large overflow: no fusion, the box is passed on
    const double gap = Tolerance::relative * size;
    // a corner of the image in no cover cannot be covered: the cheap test first, the union only for what passes it
    const auto in_cover = [&](const Vec2& p, const std::vector<Vec2>& c) {
        for (std::size_t i = 0; i < c.size(); ++i) {
            const Vec2 &a = c[i], &b = c[(i + 1) % c.size()];
            if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) < -gap * glm::length(b - a)) return false;
        }
        return true;
    };
    for (const Vec2& corner : *image)
        if (std::none_of(covers.begin(), covers.end(), [&](const std::vector<Vec2>& c) { return in_cover(corner, c); })) return 0;
    const Coverage c = covered_by_union(*image, covers, gap);
    return c.covered ? c.used : 0;
}

}  // namespace

Steps<OcclusionEvent, OcclusionCull> occlusion_cull(const Scene* scene, const Hierarchy* h, OcclusionOptions o) {
    OcclusionCull out;
    const std::size_t n = scene->polygons.size();
    out.kept = o.candidates.empty() ? std::vector<std::uint8_t>(n, 1) : o.candidates;
    const ViewPlane view = ViewPlane::of(scene->camera);
    // Choose the occluders: the best ranked
    std::vector<Candidate> ranked = occluder_candidates(*scene, out.kept, view, o.kind, o.solids);
    double extent = 1;
    for (const Aabb& b : h->boxes) extent = std::max({extent, std::abs(b.lo.x), std::abs(b.hi.x), std::abs(b.lo.y), std::abs(b.hi.y), std::abs(b.lo.z), std::abs(b.hi.z)});
    for (std::size_t k = 0; k < ranked.size() && k < o.max_occluders; ++k) {
        Candidate& c = ranked[k];
        Occluder oc{c.polygon, c.rank, c.shape, c.faces, c.outline, occlusion_frustum(c.outline, view, 1e-9 * extent), {}};
        if (o.fusion) oc.image = image_of(c.outline, view);
        out.occluders.push_back(std::move(oc));
        const OcclusionEvent chosen = OccluderChosen{c.polygon, c.rank, measure(c.outline), c.shape, std::uint32_t(c.faces.size()), std::move(c.outline)};
        co_yield chosen;
    }
    // Cull top-down: a box wholly inside one occlusion frustum goes with its subtree; with fusion, one whose image
    // the images of several cover, lying behind each of them
    const auto inside_one = [&](const Aabb& box) -> std::int32_t {
        for (std::size_t k = 0; k < out.occluders.size(); ++k)
            if (wholly_inside(box, out.occluders[k].frustum)) return std::int32_t(k);
        return -1;
    };
    const auto fused = [&](const Aabb& box) -> std::uint32_t { return o.fusion ? fused_cover(box, out.occluders, view) : 0; };
    std::uint32_t by_fusion = 0;
    const auto cull_below = [&](std::uint32_t top, bool fusion) {
        std::vector<std::uint32_t> stack{top};
        while (!stack.empty()) {
            const std::uint32_t m = stack.back();
            stack.pop_back();
            for (std::uint32_t p : h->nodes[m].primitives) out.culled += out.kept[p], by_fusion += fusion && out.kept[p], out.kept[p] = 0;
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
            cull_below(m, false);
            co_yield OcclusionTested{std::int32_t(m), -1, OcclusionOutcome::occluded, k};
            continue;
        }
        const bool touches = std::any_of(out.occluders.begin(), out.occluders.end(),
                                         [&](const Occluder& oc) { return !wholly_outside(node.box, oc.frustum); });
        if (const std::uint32_t together = touches ? fused(node.box) : 0) {
            cull_below(m, true);
            co_yield OcclusionTested{std::int32_t(m), -1, OcclusionOutcome::occluded, -1, together};
            continue;
        }
        co_yield OcclusionTested{std::int32_t(m), -1, touches ? OcclusionOutcome::partly : OcclusionOutcome::visible, -1};
        if (!touches) continue;  // outside every occlusion frustum: all of it is passed on
        for (std::uint32_t p : node.primitives) {
            if (!out.kept[p]) continue;
            const std::int32_t k = inside_one(h->boxes[p]);
            const std::uint32_t together = k < 0 ? fused(h->boxes[p]) : 0;
            if (k >= 0 || together) out.kept[p] = 0, ++out.culled, by_fusion += together > 0;
            co_yield OcclusionTested{-1, std::int32_t(p), k >= 0 || together ? OcclusionOutcome::occluded : OcclusionOutcome::visible, k, together};
        }
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.push_back(*it);
    }
    std::uint32_t passed = 0;
    for (std::uint8_t k : out.kept) passed += k;
    co_yield OcclusionFinished{std::uint32_t(out.occluders.size()), out.culled, passed, by_fusion};
    co_return out;
}

std::string_view to_string(OccluderKind k) {
    switch (k) {
        case OccluderKind::planar: return "planar";
        case OccluderKind::proxy: return "proxy";
        case OccluderKind::solid: return "solid";
    }
    return "?";
}

}  // namespace hsr::algo
