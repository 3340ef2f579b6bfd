// SPDX-License-Identifier: MIT
#include "render/depth_sort_renderer.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "render/palette.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

using algo::Vec3;

// Normalised device coordinates are left-handed (z grows away from the eye) and the 3D view is right-handed, so
// depth is drawn along −z: the eye (at z = −∞ in NDC) is on the +z side of the view, and x runs to the right, as on
// the screen and in the painted image.
glm::vec3 shown(const Vec3& ndc) { return {float(ndc.x), float(ndc.y), float(-ndc.z)}; }

glm::vec4 colour_of(const algo::SortPolygon& p, float alpha) { return {p.color.r / 255.f, p.color.g / 255.f, p.color.b / 255.f, alpha}; }

void polygon(LineBatches& out, const algo::SortPolygon& p, glm::vec4 fill, glm::vec4 edge, bool bold) {
    const auto& v = p.vertices;
    for (std::size_t k = 1; k + 1 < v.size(); ++k) out.faint.triangle(shown(v[0]), shown(v[k]), shown(v[k + 1]), fill);
    for (std::size_t k = 0; k < v.size(); ++k) (bold ? out.bold : out.faint).line(shown(v[k]), shown(v[(k + 1) % v.size()]), edge);
}

// The plane of a polygon, as a square of side 1.6 around its centre.
void plane_quad(LineBatches& out, const algo::SortPolygon& p) {
    algo::Plane pl;
    if (!algo::plane_of(p.vertices, pl)) return;
    const Vec3 c = algo::centroid(p.vertices);
    const Vec3 u = glm::normalize(glm::cross(pl.n, std::abs(pl.n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0))) * 0.8;
    const Vec3 w = glm::cross(pl.n, u);
    const glm::vec3 a = shown(c - u - w), b = shown(c + u - w), d = shown(c + u + w), e = shown(c - u + w);
    out.faint.triangle(a, b, d, palette::plane_fill);
    out.faint.triangle(a, d, e, palette::plane_fill);
    for (const auto& [x, y] : {std::pair{a, b}, {b, d}, {d, e}, {e, a}}) out.faint.line(x, y, palette::plane_edge);
}

}  // namespace

void draw_depth_sort_view(const DepthSortView& v, LineBatches& out, std::vector<Label>& labels) {
    // The canonical view volume, and where the rays come from
    const glm::vec4 box(0.6f, 0.62f, 0.66f, 0.5f);
    for (int i = 0; i < 8; ++i)
        for (int axis = 1; axis < 8; axis <<= 1)
            if (!(i & axis)) {
                const auto corner = [](int k) { return glm::vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1); };
                out.faint.line(corner(i), corner(i | axis), box);
            }
    // the eye lies far along −z, which the default orbit puts under the screen inset: a line from the volume's
    // near face towards it, labelled where it leaves the volume
    out.faint.line(shown({0, 0, -1}), shown({0, 0, -1.6}), palette::eye);
    out.bold.point(shown({0, 0, -1.6}), palette::eye);
    labels.push_back({shown({0, 0, -1}), tr("depth_sort.to_the_eye"), palette::eye});
    for (std::uint32_t i : v.list)
        if (int(i) != v.r && int(i) != v.q) polygon(out, v.polygons[i], colour_of(v.polygons[i], 0.15f), colour_of(v.polygons[i], 0.8f), false);
    for (std::uint32_t i : v.drawn) polygon(out, v.polygons[i], colour_of(v.polygons[i], 0.75f), colour_of(v.polygons[i], 1), false);
    if (v.r >= 0) {
        polygon(out, v.polygons[std::size_t(v.r)], colour_of(v.polygons[std::size_t(v.r)], 0.4f), palette::current_edge, true);
        labels.push_back({shown(algo::centroid(v.polygons[std::size_t(v.r)].vertices)), "R", palette::current_edge});
    }
    if (v.q >= 0) {
        polygon(out, v.polygons[std::size_t(v.q)], colour_of(v.polygons[std::size_t(v.q)], 0.4f), palette::parameter, true);
        labels.push_back({shown(algo::centroid(v.polygons[std::size_t(v.q)].vertices)), "Q", palette::parameter});
    }
    if (!v.tests.empty() && v.r >= 0 && v.q >= 0) {  // tests 3 and 4 test against a plane: show it
        switch (v.tests.back().test) {
            case algo::OrderTest::r_behind_q:
            case algo::OrderTest::r_in_front_of_q: plane_quad(out, v.polygons[std::size_t(v.q)]); break;
            case algo::OrderTest::q_in_front_of_r:
            case algo::OrderTest::q_behind_r: plane_quad(out, v.polygons[std::size_t(v.r)]); break;
            default: break;
        }
    }
}

}  // namespace hsr::viz
