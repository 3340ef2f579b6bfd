// SPDX-License-Identifier: MIT
#include "raster/screen_polygon.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include "clipping/straight_clip.h"
#include "core/numeric.h"
#include "core/parallel.h"
#include "core/plane.h"
#include "geometry/polygon_2d.h"

namespace hsr::algo {
namespace {

// The turn at b from edge a→b to edge b→c (twice the signed area of the triangle a, b, c).
std::int64_t turn(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
    return (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
}

// Snapping moves each vertex by up to half a sub-pixel, so an edge of a convex polygon shorter than a sub-pixel or
// two may turn the wrong way, and vertices closer than that may fall in line: the snapped polygon is then not
// convex, and the fill, which intersects the half-planes of all edges, would cut a wedge off along the long
// neighbour of such an edge. Keep the corners of the snapped polygon's convex hull (Andrew's monotone chain, exact
// in integers), in the polygon's own direction, from its first vertex that is one. A polygon that is convex after
// snapping (nearly all) is left as it is.
void keep_convex(std::vector<ScreenVertex>& v, std::int64_t area) {
    const std::size_t n = v.size();
    bool convex = true;
    for (std::size_t i = 0; i < n && convex; ++i) {
        const std::int64_t t = turn(v[i], v[(i + 1) % n], v[(i + 2) % n]);
        convex = area > 0 ? t > 0 : t < 0;
    }
    if (convex) return;
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a].x != v[b].x ? v[a].x < v[b].x : v[a].y < v[b].y; });
    std::vector<std::size_t> hull;  // lower chain, then upper chain: one turning direction throughout
    for (int pass = 0; pass < 2; ++pass) {
        const std::size_t base = hull.size();
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t i = pass == 0 ? order[k] : order[n - 1 - k];
            while (hull.size() >= base + 2 && turn(v[hull[hull.size() - 2]], v[hull.back()], v[i]) <= 0) hull.pop_back();
            hull.push_back(i);
        }
        hull.pop_back();  // each chain's last point starts the other
    }
    std::vector<ScreenVertex> corners;
    for (std::size_t i : hull) corners.push_back(v[i]);
    if ((twice_signed_area(corners) > 0) != (area > 0)) std::reverse(hull.begin(), hull.end());
    std::rotate(hull.begin(), std::min_element(hull.begin(), hull.end()), hull.end());
    corners.clear();
    for (std::size_t i : hull) corners.push_back(v[i]);
    v = std::move(corners);
}

// Newell's normal of the polygon in (x, y, d) screen space gives the depth plane d = c0 − (a/c)x − (b/c)y.
DepthPlane depth_plane(const std::vector<glm::dvec3>& v) {
    glm::dvec3 n(0), centre(0);
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
        n.x += (v[j].y - v[i].y) * (v[j].z + v[i].z);
        n.y += (v[j].z - v[i].z) * (v[j].x + v[i].x);
        n.z += (v[j].x - v[i].x) * (v[j].y + v[i].y);
        centre += v[i];
    }
    centre /= double(v.size());
    if (n.z == 0) return {centre.z, 0, 0};
    return {centre.z + (n.x * centre.x + n.y * centre.y) / n.z, -n.x / n.z, -n.y / n.z};
}

}  // namespace

void require_convex(std::span<const Vec3> v, SceneId id) {
    Plane plane;
    if (!plane_of(v, plane)) return;  // no area: the projection reports it as zero-area
    const Vec3 n = plane.n;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const Vec3 &a = v[i], &b = v[(i + 1) % v.size()], &c = v[(i + 2) % v.size()];
        if (glm::dot(glm::cross(b - a, c - b), n) < -1e-9 * glm::length(b - a) * glm::length(c - b))
            throw InvalidInput("polygon " + std::to_string(id) +
                               " is not convex; the hidden-surface algorithms here take convex polygons "
                               "(split it into triangles in the scene)");
    }
    // Every turn the same way is not enough: a pentagram turns left at each corner too, but goes round twice
    // (its turns add up to 4π, a convex polygon's to 2π).
    double turned = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const Vec3 &a = v[i], &b = v[(i + 1) % v.size()], &c = v[(i + 2) % v.size()];
        turned += std::atan2(glm::dot(glm::cross(b - a, c - b), n), glm::dot(b - a, c - b));
    }
    if (std::abs(turned) > 3 * M_PI)
        throw InvalidInput("polygon " + std::to_string(id) + " crosses itself (its edges go round " +
                           std::to_string(int(std::lround(std::abs(turned) / (2 * M_PI)))) +
                           " times, like a star); the hidden-surface algorithms here take convex polygons");
}

void require_convex(const ScenePolygon& p) {
    std::vector<Vec3> v;
    for (const auto& q : p.vertices) v.emplace_back(q);
    require_convex(v, p.id);
}

std::vector<std::string> polygons_not_convex(const Scene& scene) {
    std::vector<std::string> out;
    if (scene.coordinates != Coordinates::world) return out;
    for (const ScenePolygon& p : scene.polygons) {
        try {
            require_convex(p);
        } catch (const InvalidInput& e) {
            out.push_back(scene.source + ":" + std::to_string(p.line) + ": " + e.what());
        }
    }
    return out;
}


ScreenPolygon project_polygon(SceneId id, Color color, std::span<const glm::dvec4> clip_vertices, Viewport viewport) {
    ScreenPolygon out{.id = id, .color = color};
    // Clip in homogeneous clip space before the divide (near plane included)
    // (the straight-line form of Sutherland–Hodgman: the machine's answer bit for bit, without its events, which
    // no view of the z-buffer shows; clipping/straight_clip.h)
    for (const auto& v : clip_vertices) require_finite(v, [&] { return "polygon " + std::to_string(id); });
    // Wholly inside every plane (most polygons of a scene): each of the 7 stages would only pass the list on, one
    // place turned (it emits the end of each edge), so the answer is the list turned by 7, with no clipping work.
    const bool inside = std::all_of(clip_vertices.begin(), clip_vertices.end(), [](const glm::dvec4& v) { return plain_outcode(v) == 0; });
    const bool clip = !inside || clip_vertices.empty();
    std::vector<glm::dvec4> clipped;
    if (clip) clipped = plain_sutherland_hodgman(std::vector<glm::dvec4>(clip_vertices.begin(), clip_vertices.end()));
    const std::span<const glm::dvec4> visible = clip ? std::span<const glm::dvec4>(clipped) : clip_vertices;
    if (visible.size() < 3) {
        out.status = ScreenStatus::outside_view;
        return out;
    }
    // Divide by w, map to the viewport, snap to sub-pixels (the unsnapped positions kept for the depth plane, in a
    // buffer each thread reuses: a scene has many polygons and few vertices each)
    thread_local std::vector<glm::dvec3> exact;
    exact.clear();
    out.vertices.reserve(visible.size());
    const std::size_t first = clip ? 0 : 7 % visible.size();  // the list turned by 7, read in place
    for (std::size_t k = 0; k < visible.size(); ++k) {
        const glm::dvec4& c = visible[(first + k) % visible.size()];
        glm::dvec3 ndc = glm::dvec3(c) / c.w;
        // Clipped, the polygon lies in the view volume but for rounding; with coordinates near the double limits the
        // rounding is all there is, and the sub-pixel integers below would overflow. Keep x and y in [−1, 1], and
        // refuse what overflowed outright.
        if (!std::isfinite(ndc.x) || !std::isfinite(ndc.y) || !std::isfinite(ndc.z))
            throw InvalidInput("polygon " + std::to_string(id) + " is too large to project: its clip-space coordinates overflow");
        ndc.x = std::clamp(ndc.x, -1.0, 1.0), ndc.y = std::clamp(ndc.y, -1.0, 1.0);
        const glm::dvec3 s((ndc.x + 1) * 0.5 * viewport.width, (1 - ndc.y) * 0.5 * viewport.height, (ndc.z + 1) * 0.5);
        const ScreenVertex v{round_half_away(s.x * subpixels), round_half_away(s.y * subpixels), std::clamp(s.z, 0.0, 1.0)};
        if (out.vertices.empty() || v.x != out.vertices.back().x || v.y != out.vertices.back().y) {
            out.vertices.push_back(v);
            exact.push_back(s);
        }
    }
    while (out.vertices.size() > 1 && out.vertices.front().x == out.vertices.back().x &&
           out.vertices.front().y == out.vertices.back().y) {
        out.vertices.pop_back();
        exact.pop_back();
    }
    const std::int64_t area = twice_signed_area(out.vertices);  // sub-pixels², > 0 clockwise on the screen (y down)
    if (area == 0) {
        out.status = ScreenStatus::zero_area;
        return out;
    }
    if (area < 0) {  // counter-clockwise on screen: walk it the other way
        std::reverse(out.vertices.begin(), out.vertices.end());
        std::reverse(exact.begin(), exact.end());
    }
    out.plane = depth_plane(exact);  // from every vertex, before snapping may drop some
    keep_convex(out.vertices, std::abs(area));
    std::int64_t y0 = out.vertices[0].y, y1 = y0;
    for (const auto& v : out.vertices) y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
    out.row_begin = int(std::clamp<std::int64_t>(ceil_div(y0 - subpixels / 2, subpixels), 0, viewport.height));
    out.row_end = int(std::clamp<std::int64_t>(floor_div(y1 - subpixels / 2, subpixels) + 1, 0, viewport.height));
    return out;
}

ScreenPolygon project_polygon(SceneId id, Color color, const std::vector<glm::dvec4>& clip_vertices, Viewport viewport) {
    return project_polygon(id, color, std::span<const glm::dvec4>(clip_vertices), viewport);
}

std::vector<ScreenPolygon> project_polygons(std::span<const ClipSpacePolygon> polygons, Viewport viewport) {
    std::vector<ScreenPolygon> out(polygons.size());
    for_each_chunk(polygons.size(), 2000, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t k = begin; k < end; ++k) out[k] = project_polygon(polygons[k].id, polygons[k].color, polygons[k].vertices, viewport);
    });
    return out;
}

std::vector<ScreenPolygon> project_polygons(const Scene& scene, Viewport viewport) {
    // in chunks on every core (a city has 10^6 triangles), each chunk's answers in the scene's order
    std::vector<std::vector<ScreenPolygon>> chunks(worker_count());
    const glm::dmat4 to_clip_space = view_projection(scene.camera);  // to_clip's matrix, made once
    for_each_chunk(scene.polygons.size(), 2000, [&](std::size_t begin, std::size_t end, std::size_t chunk) {
        std::vector<glm::dvec4> clip;
        for (std::size_t i = begin; i < end; ++i) {
            const ScenePolygon& p = scene.polygons[i];
            for (std::size_t k = 0; k < p.vertices.size(); ++k)
                require_finite(p.vertices[k], [&] { return "polygon " + std::to_string(p.id) + " vertex " + std::to_string(k); });
            if (p.vertices.size() < 3) continue;  // a 2D segment: nothing to fill
            if (scene.coordinates == Coordinates::world) require_convex(p);
            clip.clear();
            for (const auto& v : p.vertices) clip.push_back(scene.coordinates == Coordinates::clip ? v : to_clip_space * v);
            chunks[chunk].push_back(project_polygon(p.id, p.color, std::span<const glm::dvec4>(clip), viewport));
        }
    });
    std::vector<ScreenPolygon> out = std::move(chunks[0]);
    for (std::size_t k = 1; k < chunks.size(); ++k) std::move(chunks[k].begin(), chunks[k].end(), std::back_inserter(out));
    return out;
}

int edge_bound_on_row(const ScreenVertex& a, const ScreenVertex& b, int row) {
    // E(p) = dx·(p.y − a.y) − dy·(p.x − a.x) ≥ t, with p.x = 256·i + 128 the centre of pixel i
    const std::int64_t dx = b.x - a.x, dy = b.y - a.y, t = fill_rule_threshold(dx, dy);
    const std::int64_t k = dx * (row_centre(row) - a.y) + dy * a.x;  // E = −dy·p.x + k
    const std::int64_t half = subpixels / 2;
    if (dy < 0) return int(std::clamp<std::int64_t>(ceil_div(t - k + half * dy, -subpixels * dy), -1, 1 << 30));
    return int(std::clamp<std::int64_t>(floor_div(k - half * dy - t, subpixels * dy) + 1, -1, 1 << 30));
}

double edge_x_at_row(const ScreenVertex& a, const ScreenVertex& b, int row) {
    const double y = double(row_centre(row));
    return (double(a.x) + double(b.x - a.x) * (y - double(a.y)) / double(b.y - a.y)) / double(subpixels);
}

Span span_on_row(const ScreenPolygon& p, int row, Viewport viewport) {
    Span s{0, viewport.width};
    if (p.status != ScreenStatus::drawn || row < p.row_begin || row >= p.row_end) return {0, 0};
    for (std::size_t i = 0, j = p.vertices.size() - 1; i < p.vertices.size(); j = i++) {
        const ScreenVertex &a = p.vertices[j], &b = p.vertices[i];
        const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
        if (dy < 0) s.begin = std::max(s.begin, edge_bound_on_row(a, b, row));
        else if (dy > 0) s.end = std::min(s.end, edge_bound_on_row(a, b, row));
        else if (dx * (row_centre(row) - a.y) < fill_rule_threshold(dx, dy)) return {0, 0};  // outside a horizontal edge
    }
    return s;
}

}  // namespace hsr::algo
