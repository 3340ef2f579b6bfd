// SPDX-License-Identifier: MIT
#include "roberts/hidden_lines.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include <glm/glm.hpp>

#include "core/numeric.h"
#include "geometry/half_space_cut.h"
#include "geometry/polygon_2d.h"
#include "geometry/union_find.h"

namespace hsr::algo {
namespace {

Vec3 world(const glm::dvec4& v) { return Vec3(v); }

std::vector<Vec3> face_vertices(const Scene& scene, std::uint32_t face) {
    std::vector<Vec3> v;
    for (const auto& p : scene.polygons[face].vertices) v.push_back(world(p));
    return v;
}

// Vertices ordered by their coordinates, so that equal points are one key.
struct ByCoordinates {
    bool operator()(const Vec3& a, const Vec3& b) const { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); }
};

}  // namespace

LineDrawingInput convex_bodies(const Scene& scene) {
    if (scene.coordinates != Coordinates::world) throw InvalidInput("Roberts' hidden lines need a scene in world coordinates");
    const auto n = std::uint32_t(scene.polygons.size());
    const glm::dmat4 m = view_projection(scene.camera);
    const auto name = [&](std::uint32_t f) {
        const ScenePolygon& p = scene.polygons[f];
        return (p.line ? "line " + std::to_string(p.line) + ": " : std::string()) + "polygon " + std::to_string(p.id);
    };
    // The edges, by their two vertices (exactly equal coordinates are one vertex)
    std::map<Vec3, std::uint32_t, ByCoordinates> vertex_ids;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> faces_of;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<Vec3, Vec3>> ends;
    for (std::uint32_t f = 0; f < n; ++f) {
        const std::vector<Vec3> v = face_vertices(scene, f);
        if (v.size() < 3) throw InvalidInput(name(f) + ": Roberts' bodies are made of polygons (3 or more vertices)");
        for (const Vec3& p : v) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) throw InvalidInput(name(f) + ": a vertex is not a finite number");
            if ((m * glm::dvec4(p, 1)).w <= 1e-12) throw InvalidInput(name(f) + ": reaches behind the eye (Roberts' transform needs every body in front)");
        }
        for (std::size_t i = 0; i < v.size(); ++i) {
            const Vec3 &a = v[i], &b = v[(i + 1) % v.size()];
            const auto ia = vertex_ids.emplace(a, std::uint32_t(vertex_ids.size())).first->second;
            const auto ib = vertex_ids.emplace(b, std::uint32_t(vertex_ids.size())).first->second;
            if (ia == ib) continue;
            const auto key = std::minmax(ia, ib);
            faces_of[key].push_back(f);
            ends.emplace(key, std::pair{a, b});
        }
    }
    UnionFind groups(n);  // over the polygons: bodies of faces that share edges
    for (const auto& [key, faces] : faces_of) {
        if (faces.size() != 2)
            throw InvalidInput(name(faces.front()) + (faces.size() < 2 ? ": an edge with no second face (Roberts' bodies are closed)"
                                                                          : ": an edge shared by more than two faces"));
        groups.join(faces[0], faces[1]);
    }
    LineDrawingInput out;
    std::map<std::size_t, std::uint32_t> body_of_root;
    std::vector<std::uint32_t> body_of(n);
    for (std::uint32_t f = 0; f < n; ++f) {
        const auto [it, added] = body_of_root.emplace(groups.find(f), std::uint32_t(out.bodies.size()));
        if (added) out.bodies.emplace_back();
        out.bodies[it->second].faces.push_back(f);
        body_of[f] = it->second;
    }
    // Outward planes (about the body's centroid, which lies inside a convex body), and convexity
    for (ConvexBody& body : out.bodies) {
        std::vector<Vec3> all;
        for (std::uint32_t f : body.faces)
            for (const Vec3& p : face_vertices(scene, f)) all.push_back(p);
        Vec3 centre(0);
        double size = 0;
        for (const Vec3& p : all) centre += p / double(all.size());
        for (const Vec3& p : all) size = std::max(size, glm::length(p - centre));
        for (std::uint32_t f : body.faces) {
            Plane plane;
            if (!plane_of(face_vertices(scene, f), plane)) throw InvalidInput(name(f) + ": a face with no area");
            if (plane.distance(centre) > 0) plane = {-plane.n, -plane.d};
            for (const Vec3& p : all)
                if (plane.distance(p) > 1e-9 * size) throw InvalidInput(name(f) + ": its body is not convex (a vertex lies outside this face's plane)");
            body.planes.push_back(plane);
        }
    }
    for (const auto& [key, faces] : faces_of) out.edges.push_back({body_of[faces[0]], ends[key].first, ends[key].second, {faces[0], faces[1]}});
    return out;
}

std::optional<std::pair<double, double>> hidden_part(const Camera& camera, const ConvexBody& body, const Scene& scene, Vec3 a, Vec3 b) {
    const glm::dmat4 m = view_projection(camera);
    const glm::dvec4 ca = m * glm::dvec4(a, 1), cb = m * glm::dvec4(b, 1);
    const Vec3 na = Vec3(ca) / ca.w, nb = Vec3(cb) / cb.w;  // the edge's ends after the transform (NDC)
    // The body's faces after the transform, outward about its transformed centroid
    std::vector<std::vector<Vec3>> faces;
    Vec3 centre(0);
    std::size_t count = 0;
    double z_min = std::min(na.z, nb.z), z_max = std::max(na.z, nb.z);
    for (std::uint32_t f : body.faces) {
        std::vector<Vec3> v;
        for (const auto& p : scene.polygons[f].vertices) {
            const glm::dvec4 c = m * glm::dvec4(Vec3(p), 1);
            v.push_back(Vec3(c) / c.w);
            centre += v.back(), ++count;
            z_min = std::min(z_min, v.back().z), z_max = std::max(z_max, v.back().z);
        }
        faces.push_back(std::move(v));
    }
    centre /= double(count);
    // (t, s): the point na + t·(nb − na), moved toward the eye by s along v = (0, 0, −1), no farther than past the body
    const Vec3 d = nb - na, toward_eye(0, 0, -1);
    std::vector<glm::dvec2> region = {{0, 0}, {1, 0}, {1, z_max - z_min + 1}, {0, z_max - z_min + 1}};
    const double eps = 1e-12 * std::max(1.0, z_max - z_min);  // touching is not hiding
    for (const auto& v : faces) {
        Plane plane;
        if (!plane_of(v, plane)) continue;
        if (plane.distance(centre) > 0) plane = {-plane.n, -plane.d};
        const double c0 = glm::dot(plane.n, na) + plane.d + eps, ct = glm::dot(plane.n, d), cs = glm::dot(plane.n, toward_eye);
        region = cut_polygon(region, [&](glm::dvec2 p) { return -(c0 + ct * p.x + cs * p.y); });  // keep c0 + ct·t + cs·s ≤ 0
        if (region.size() < 3) return std::nullopt;
    }
    if (area(region) <= 1e-18) return std::nullopt;
    double t0 = 1, t1 = 0;
    for (const glm::dvec2& p : region) t0 = std::min(t0, p.x), t1 = std::max(t1, p.x);
    // back from the transformed segment's parameter to the world's: t′ = t·w_b / ((1 − t)·w_a + t·w_b)
    const auto to_world = [&](double tp) { return tp * ca.w / (cb.w * (1 - tp) + tp * ca.w); };
    t0 = std::clamp(to_world(std::clamp(t0, 0.0, 1.0)), 0.0, 1.0), t1 = std::clamp(to_world(std::clamp(t1, 0.0, 1.0)), 0.0, 1.0);
    if (!(t1 > t0)) return std::nullopt;
    return std::pair{t0, t1};
}

Steps<RobertsEvent, LineDrawing> roberts(Scene scene, RobertsOptions o) {
    LineDrawing out;
    out.input = convex_bodies(scene);
    const LineDrawingInput& in = out.input;
    out.edges.resize(in.edges.size());
    co_yield BodiesFound{std::uint32_t(in.bodies.size()), std::uint32_t(in.edges.size())};
    const Camera& camera = scene.camera;
    const auto faces_eye = [&](std::uint32_t face, std::uint32_t body) {
        const ConvexBody& b = in.bodies[body];
        const auto k = std::size_t(std::find(b.faces.begin(), b.faces.end(), face) - b.faces.begin());
        const Plane& p = b.planes[k];
        if (camera.projection == Projection::orthographic) return glm::dot(p.n, camera.eye - camera.target) > 0;
        return p.distance(camera.eye) > 0;
    };
    std::uint32_t drawn = 0, removed = 0;
    for (std::uint32_t e = 0; e < in.edges.size(); ++e) {
        const BodyEdge& edge = in.edges[e];
        if (!faces_eye(edge.faces[0], edge.body) && !faces_eye(edge.faces[1], edge.body)) {
            out.edges[e].removed = true, ++removed;
            co_yield EdgeRemoved{e, edge.body};
            continue;
        }
        std::vector<std::pair<double, double>> parts;
        for (std::uint32_t by = 0; by < in.bodies.size(); ++by) {
            if (by == edge.body) continue;
            if (++out.tests > o.max_tests) {
                out.bounded = true;
                co_yield RobertsFinished{drawn, removed, out.tests - 1, true};
                co_return out;
            }
            const auto part = hidden_part(camera, in.bodies[by], scene, edge.a, edge.b);
            if (part) parts.push_back(*part);
            co_yield EdgeTested{e, edge.body, by, part.has_value(), part ? part->first : 0, part ? part->second : 0};
        }
        // merge the hidden parts; what is left is drawn
        std::sort(parts.begin(), parts.end());
        std::vector<std::pair<double, double>> merged;
        for (const auto& p : parts)
            if (!merged.empty() && p.first <= merged.back().second) merged.back().second = std::max(merged.back().second, p.second);
            else merged.push_back(p);
        double hidden = 0;
        std::uint32_t pieces = 0;
        double at = 0;
        for (const auto& [t0, t1] : merged) {
            hidden += t1 - t0;
            pieces += t0 > at;
            at = t1;
        }
        pieces += at < 1;
        out.edges[e].hidden = merged;
        drawn += pieces > 0;
        co_yield EdgeFinished{e, hidden, pieces};
    }
    co_yield RobertsFinished{drawn, removed, out.tests, false};
    co_return out;
}

}  // namespace hsr::algo
