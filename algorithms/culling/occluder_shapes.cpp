// SPDX-License-Identifier: MIT
#include "culling/occluder_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include <glm/geometric.hpp>

#include "culling/bounding_volume.h"
#include "geometry/half_space_cut.h"


namespace hsr::algo {

// ── the view plane ──────────────────────────────────────────────────────────────────────────────────────────
ViewPlane ViewPlane::of(const Camera& c) {
    ViewPlane v;
    v.eye = c.eye;
    const Vec3 d = c.target - c.eye;
    v.direction = glm::length(d) > 0 ? glm::normalize(d) : Vec3(0, 0, -1);
    Vec3 r = glm::cross(v.direction, c.up);
    if (glm::length(r) == 0) r = glm::cross(v.direction, std::abs(v.direction.y) < 0.9 ? Vec3(0, 1, 0) : Vec3(1, 0, 0));
    v.right = glm::normalize(r);
    v.up = glm::cross(v.right, v.direction);
    v.orthographic = c.projection == Projection::orthographic;
    v.near = c.near;
    return v;
}

double ViewPlane::depth(const Vec3& p) const { return glm::dot(p - eye, direction); }

std::optional<Vec2> ViewPlane::image(const Vec3& p) const {
    const Vec3 q = p - eye;
    const Vec2 across{glm::dot(q, right), glm::dot(q, up)};
    if (orthographic) return across;
    const double z = glm::dot(q, direction);
    if (!(z > 0)) return std::nullopt;
    const Vec2 at = across / z;
    if (!std::isfinite(at.x) || !std::isfinite(at.y)) return std::nullopt;
    return at;
}

Vec3 ViewPlane::point(const Vec2& at, double z) const {
    const Vec2 across = orthographic ? at : at * z;
    return eye + right * across.x + up * across.y + direction * z;
}

// ── hulls and proxies ───────────────────────────────────────────────────────────────────────────────────────
namespace {
double perimeter(const std::vector<Vec2>& p) {
    double s = 0;
    for (std::size_t i = 0; i < p.size(); ++i) s += glm::length(p[(i + 1) % p.size()] - p[i]);
    return s;
}
// Thinner than `gap` everywhere: twice the area over the perimeter is about the width of a long thin piece.
bool thinner_than(const std::vector<Vec2>& p, double gap) { return p.size() < 3 || 2 * std::abs(signed_area(p)) <= gap * perimeter(p); }
}  // namespace

std::optional<std::vector<Vec3>> proxy_of(std::span<const Vec3> vertices, const ViewPlane& view) {
    std::vector<Vec2> images;
    double far = -1e308;
    for (const Vec3& v : vertices) {
        const double z = view.depth(v);
        if (!(z >= view.near)) return std::nullopt;
        const auto at = view.image(v);
        if (!at) return std::nullopt;
        images.push_back(*at);
        far = std::max(far, z);
    }
    const std::vector<Vec2> hull = convex_hull(std::move(images));
    if (hull.size() < 3 || !(signed_area(hull) > 0) || !std::isfinite(far)) return std::nullopt;
    std::vector<Vec3> out;
    for (const Vec2& at : hull) out.push_back(view.point(at, far));
    return out;
}

// ── convex solids ───────────────────────────────────────────────────────────────────────────────────────────
std::vector<std::vector<std::uint32_t>> convex_solids(const Scene& scene) {
    std::vector<std::vector<Vec3>> polygons;
    for (const ScenePolygon& p : scene.polygons) {
        polygons.emplace_back();
        for (const auto& v : p.vertices) polygons.back().emplace_back(v);
    }
    std::vector<std::vector<std::uint32_t>> out;
    for (const std::vector<std::size_t>& object : connected_objects(polygons)) {  // joined through shared vertices
        if (object.size() < 4) continue;
        // closed: each directed edge once, and its reverse once (the same vertex is the same point, bit for bit)
        std::map<std::array<double, 3>, std::uint32_t> vertex_id;
        const auto id = [&](const Vec3& v) { return vertex_id.emplace(std::array<double, 3>{v.x, v.y, v.z}, std::uint32_t(vertex_id.size())).first->second; };
        std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
        for (std::size_t i : object)
            for (std::size_t k = 0; k < polygons[i].size(); ++k) edges.push_back({id(polygons[i][k]), id(polygons[i][(k + 1) % polygons[i].size()])});
        std::sort(edges.begin(), edges.end());
        const bool closed = std::adjacent_find(edges.begin(), edges.end()) == edges.end() &&
                            std::all_of(edges.begin(), edges.end(), [&](const auto& e) {
                                return std::binary_search(edges.begin(), edges.end(), std::pair{e.second, e.first});
                            });
        if (!closed) continue;
        // convex: every vertex on or behind every face's plane (outward normals by the counter-clockwise winding)
        std::vector<Vec3> points;
        for (std::size_t i : object) points.insert(points.end(), polygons[i].begin(), polygons[i].end());
        const Tolerance tol = Tolerance::for_points(points);
        const bool convex = std::all_of(object.begin(), object.end(), [&](std::size_t i) {
            Plane p;
            return plane_of(polygons[i], p) && std::all_of(points.begin(), points.end(), [&](const Vec3& q) { return p.distance(q) <= tol.epsilon; });
        });
        if (convex) out.emplace_back(object.begin(), object.end());
    }
    return out;
}

// ── fusion ──────────────────────────────────────────────────────────────────────────────────────────────────
namespace {
// The part of a convex polygon on the left of the directed line a → b (keep_left) or on its right.
std::vector<Vec2> clip_to_side(const std::vector<Vec2>& poly, const Vec2& a, const Vec2& b, bool keep_left) {
    return cut_polygon(poly, [&](const Vec2& p) { return keep_left ? orientation(a, b, p) : -orientation(a, b, p); });
}
}  // namespace

Coverage covered_by_union(const std::vector<Vec2>& image, std::span<const std::vector<Vec2>> covers, double gap, std::size_t max_pieces) {
    Coverage c;
    if (thinner_than(image, gap)) return {false, 0, std::abs(signed_area(image))};  // nothing to cover is no proof of being hidden
    std::vector<std::vector<Vec2>> left{image};  // what no cover has taken yet, in convex pieces
    for (const std::vector<Vec2>& cover : covers) {
        if (left.empty()) break;
        bool took = false;
        std::vector<std::vector<Vec2>> next;
        for (const std::vector<Vec2>& piece : left) {
            // piece − cover: the parts outside each edge of the cover in turn, and what is inside them all goes
            std::vector<std::vector<Vec2>> outside;
            std::vector<Vec2> inside = piece;
            for (std::size_t e = 0; e < cover.size() && !thinner_than(inside, gap); ++e) {
                const Vec2 &a = cover[e], &b = cover[(e + 1) % cover.size()];
                if (auto out = clip_to_side(inside, a, b, false); !thinner_than(out, gap)) outside.push_back(std::move(out));
                inside = clip_to_side(inside, a, b, true);
            }
            if (thinner_than(inside, gap)) {
                next.push_back(piece);  // the cover missed it (or only grazed it): keep it whole
                continue;
            }
            took = true;
            for (auto& o : outside) next.push_back(std::move(o));
        }
        c.used += took;
        left = std::move(next);
        if (left.size() > max_pieces) break;
    }
    for (const auto& piece : left) c.area_left += std::abs(signed_area(piece));
    c.covered = left.empty();
    return c;
}

std::optional<std::vector<Vec2>> box_image(const Aabb& box, const ViewPlane& view) {
    std::vector<Vec2> corners;
    for (int k = 0; k < 8; ++k) {
        const auto at = view.image(box.corner(k));
        if (!at) return std::nullopt;
        corners.push_back(*at);
    }
    return convex_hull(std::move(corners));
}

}  // namespace hsr::algo
