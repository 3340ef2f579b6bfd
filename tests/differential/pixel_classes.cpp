// SPDX-License-Identifier: MIT
#include "pixel_classes.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace hsr::test {
namespace {

// Sutherland–Hodgman against one plane of clip space, kept when dot(plane, v) ≥ 0.
std::vector<glm::dvec4> clip_against(const std::vector<glm::dvec4>& in, const glm::dvec4& plane) {
    std::vector<glm::dvec4> out;
    for (std::size_t k = 0; k < in.size(); ++k) {
        const glm::dvec4 &p = in[k], &q = in[(k + 1) % in.size()];
        const double dp = glm::dot(plane, p), dq = glm::dot(plane, q);
        if (dp >= 0) out.push_back(p);
        if ((dp >= 0) != (dq >= 0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
    }
    return out;
}

double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + ab * t));
}

}  // namespace

Outline screen_outline(std::span<const glm::dvec4> clip, algo::Viewport vp) {
    std::vector<glm::dvec4> v(clip.begin(), clip.end());
    v = clip_against(v, {0, 0, 1, 1});   // near: z ≥ −w
    v = clip_against(v, {0, 0, -1, 1});  // far: z ≤ w
    Outline o;
    for (const glm::dvec4& c : v)
        o.screen.emplace_back((c.x / c.w + 1) / 2 * vp.width, (1 - c.y / c.w) / 2 * vp.height, (c.z / c.w + 1) / 2);
    return o;
}

bool near_outline(const Outline& o, glm::dvec2 at, double distance) {
    for (std::size_t k = 0; k < o.screen.size(); ++k) {
        const glm::dvec3 &a = o.screen[k], &b = o.screen[(k + 1) % o.screen.size()];
        if (distance_to_segment(at, {a.x, a.y}, {b.x, b.y}) <= distance) return true;
    }
    return false;
}

std::optional<double> depth_at(const Outline& o, glm::dvec2 at) {
    if (o.screen.size() < 3) return std::nullopt;
    glm::dvec3 n(0), centre(0);
    for (std::size_t k = 0; k < o.screen.size(); ++k) {  // Newell's normal: sound for any planar polygon
        const glm::dvec3 &p = o.screen[k], &q = o.screen[(k + 1) % o.screen.size()];
        n += glm::dvec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
        centre += p;
    }
    centre /= double(o.screen.size());
    if (!(std::abs(n.z) > 1e-12 * glm::length(n))) return std::nullopt;  // edge-on (or degenerate)
    return centre.z - (n.x * (at.x - centre.x) + n.y * (at.y - centre.y)) / n.z;
}

Outlines scene_outlines(const algo::Scene& s, algo::Viewport vp) {
    Outlines out;
    const glm::dmat4 m = algo::view_projection(s.camera);
    for (const algo::ScenePolygon& p : s.polygons) {
        std::vector<glm::dvec4> clip;
        for (const glm::dvec4& v : p.vertices) clip.push_back(m * v);
        add_outline(out, p.id, clip, vp);
    }
    return out;
}

void add_outline(Outlines& to, algo::SceneId id, std::span<const glm::dvec4> clip, algo::Viewport vp) {
    to[id].push_back(screen_outline(clip, vp));
}

PixelClass classify(int x, int y, algo::SceneId a, algo::SceneId b, const Outlines& scene, const Outlines& parts, const TieRule& tie) {
    if (a == b) return PixelClass::same;
    const glm::dvec2 centre(x + 0.5, y + 0.5);
    for (const algo::SceneId id : {a, b})
        for (const Outlines* outlines : {&scene, &parts})
            if (const auto found = outlines->find(id); id != 0 && found != outlines->end())
                for (const Outline& o : found->second)
                    if (near_outline(o, centre, edge_distance)) return PixelClass::edge;
    if (a == 0 || b == 0) return PixelClass::unexplained;  // a polygon's inside, shown by one and not the other
    const auto in_a = scene.find(a), in_b = scene.find(b);
    if (in_a == scene.end() || in_b == scene.end()) return PixelClass::unexplained;
    const auto da = depth_at(in_a->second.front(), centre), db = depth_at(in_b->second.front(), centre);
    if (!da || !db) return PixelClass::unexplained;
    for (const algo::DepthFormat f : tie.formats) {
        const std::uint64_t ca = algo::code_of_window_depth(f, *da, tie.range, tie.perspective),
                            cb = algo::code_of_window_depth(f, *db, tie.range, tie.perspective);
        if ((ca > cb ? ca - cb : cb - ca) <= tie.codes) return PixelClass::tie;
    }
    return PixelClass::unexplained;
}

Tally& Tally::operator+=(const Tally& t) {
    compared += t.compared, differ += t.differ, edge += t.edge, tie += t.tie, unexplained += t.unexplained;
    return *this;
}

Tally compare_images(const std::vector<algo::SceneId>& ours, const std::vector<algo::SceneId>& reference, algo::Viewport vp,
                     const Outlines& scene, const Outlines& parts, const TieRule& tie, std::vector<std::string>* first_unexplained,
                     std::size_t keep) {
    Tally t;
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x) {
            const std::size_t k = std::size_t(y) * std::size_t(vp.width) + std::size_t(x);
            ++t.compared;
            switch (classify(x, y, ours[k], reference[k], scene, parts, tie)) {
                case PixelClass::same: continue;
                case PixelClass::edge: ++t.edge; break;
                case PixelClass::tie: ++t.tie; break;
                case PixelClass::unexplained:
                    ++t.unexplained;
                    if (first_unexplained && first_unexplained->size() < keep)
                        first_unexplained->push_back("(" + std::to_string(x) + ", " + std::to_string(y) + "): " + std::to_string(ours[k]) +
                                                     ", reference " + std::to_string(reference[k]));
                    break;
            }
            ++t.differ;
        }
    return t;
}

}  // namespace hsr::test
