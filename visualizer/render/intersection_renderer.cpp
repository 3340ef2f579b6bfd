// SPDX-License-Identifier: MIT
#include "render/intersection_renderer.h"

#include <cmath>

#include "render/palette.h"
#include "render/scene_color.h"
#include "state/state_colours.h"
#include "state/strings.h"
#include "volumes/kdop.h"

namespace hsr::viz {

using algo::Vec3;

namespace {

constexpr int box_edges[12][2] = {{0, 1}, {1, 3}, {3, 2}, {2, 0}, {4, 5}, {5, 7}, {7, 6}, {6, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
// the legend's colours (state/state_colours.h), at the strength each is drawn with
glm::vec4 rgba(const StateColour& c, float alpha) { return {c.r, c.g, c.b, alpha}; }
const glm::vec4 missed = rgba(intersection_colours::missed, 0.7f), alarm = rgba(intersection_colours::false_alarm, 0.9f),
                met = rgba(intersection_colours::met, 0.7f), at_work = rgba(intersection_colours::at_work, 1),
                visited{0.75f, 0.77f, 0.82f, 0.35f};

glm::vec3 f(const Vec3& v) { return glm::vec3(v); }

void box(LineBatch& out, const std::array<Vec3, 8>& c, glm::vec4 colour) {
    for (const auto& [i, j] : box_edges) out.line(f(c[std::size_t(i)]), f(c[std::size_t(j)]), colour);
}

// A node's volume (k: the hull to draw, for hulls; 0: all of them).
void volume(LineBatch& out, const algo::NodeVolume& v, algo::VolumeKind kind, std::uint32_t k, glm::vec4 colour) {
    std::array<Vec3, 8> c{};
    switch (kind) {
        case algo::VolumeKind::aabb:
            for (int i = 0; i < 8; ++i) c[std::size_t(i)] = v.box.corner(i);
            return box(out, c, colour);
        case algo::VolumeKind::obb:
            for (int i = 0; i < 8; ++i) c[std::size_t(i)] = v.obb.corner(i);
            return box(out, c, colour);
        case algo::VolumeKind::sphere:  // three great circles
            for (int axis = 0; axis < 3; ++axis)
                for (int s = 0; s < 48; ++s) {
                    const auto at = [&](int i) {
                        const double a = 2 * M_PI * i / 48;
                        Vec3 p(0);
                        p[(axis + 1) % 3] = std::cos(a), p[(axis + 2) % 3] = std::sin(a);
                        return f(v.sphere.centre + v.sphere.radius * p);
                    };
                    out.line(at(s), at(s + 1), colour);
                }
            return;
        case algo::VolumeKind::kdop:
        case algo::VolumeKind::hulls:
            for (const algo::KDop& dop : v.dops) {
                if (k != 0 && std::uint32_t(dop.k) != k) continue;
                for (const auto& face : algo::kdop_faces(dop))
                    for (std::size_t i = 0; i < face.size(); ++i) out.line(f(face[i]), f(face[(i + 1) % face.size()]), colour);
            }
            return;
    }
}

}  // namespace

void draw_intersection_view(const IntersectionView& v, const algo::Scene& scene, LineBatches& out, std::vector<Label>& labels) {
    const IntersectionInput& in = *v.input;
    const algo::BoundingModel& m = in.model;
    const SceneColors colours(scene);
    for (std::size_t p = 0; p < m.polygons.size(); ++p) {
        const auto& poly = m.polygons[p];
        const bool testing = v.primitive && v.primitive->polygon == p;
        for (std::size_t i = 0; i < poly.size(); ++i)
            (testing ? out.bold : out.faint).line(f(poly[i]), f(poly[(i + 1) % poly.size()]),
                                                  testing ? (v.primitive->hit ? met : missed) : colours(m.ids[p], 0.5f));
        if (poly.size() >= 3) out.faint.triangle(f(poly[0]), f(poly[1]), f(poly[2]), colours(m.ids[p], 0.18f));
    }
    // the nodes this ray has reached, by what they were
    for (std::size_t node = 0; node < v.marks.size(); ++node) {
        switch (v.marks[node]) {
            case CallMark::missed: volume(out.faint, m.volumes[node], m.options.volume, 0, missed); break;
            case CallMark::false_alarm: volume(out.faint, m.volumes[node], m.options.volume, 0, alarm); break;
            case CallMark::hit: volume(out.faint, m.volumes[node], m.options.volume, 0, met); break;
            case CallMark::inside:
            case CallMark::entered: volume(out.faint, m.volumes[node], m.options.volume, 0, visited); break;
            case CallMark::untouched:
            case CallMark::skipped: break;
        }
    }
    if (v.volume && !v.calls.empty() && v.calls.back() == v.volume->node)  // the volume just tested, bold: yellow when met, blue when missed
        volume(out.bold, m.volumes[v.volume->node], m.options.volume, v.volume->k, v.volume->hit ? at_work : rgba(intersection_colours::missed, 1));
    else if (!v.calls.empty() && m.tree.nodes[v.calls.back()].children.empty() && v.marks.size() > v.calls.back())
        volume(out.faint, m.volumes[v.calls.back()], algo::VolumeKind::aabb, 0, palette::current_edge);  // a bottom level: its box, faint
    // the rays: the one under test bold, from its origin past the scene
    const double reach = 2 * glm::length(m.volumes.empty() ? Vec3(10) : m.tree.nodes[0].box.size()) + 1;
    for (std::size_t r = 0; r < in.rays.size(); ++r) {
        const algo::Ray& ray = in.rays[r];
        const Vec3 end = ray.origin + glm::normalize(ray.direction) * (glm::length(ray.origin - m.tree.nodes[0].box.centre()) + reach);
        const bool current = v.ray == r;
        const glm::vec4 colour = current ? palette::current_edge : glm::vec4(0.8f, 0.8f, 0.8f, 0.45f);
        (current ? out.bold : out.faint).line(f(ray.origin), f(end), colour);
        out.bold.point(f(ray.origin), colour);
        labels.push_back({f(ray.origin), tr("intersection.ray_label", {{"ray", std::to_string(r)}}), colour});
    }
    if (v.hit_point) out.bold.point(f(*v.hit_point), met);
    // the nodes the narration and the questions name: those on the call stack, the one just tested, a component the
    // || skipped; at the top of its box, in the colour of what it was
    const auto label_node = [&](std::uint32_t node, glm::vec4 colour) {
        if (node >= m.tree.nodes.size()) return;
        const algo::Aabb& b = m.tree.nodes[node].box;
        labels.push_back({glm::vec3(b.centre().x, b.hi.y, b.centre().z), tr("intersection.node_label", {{"node", std::to_string(node)}}), colour});
    };
    for (const std::uint32_t node : v.calls) label_node(node, at_work);
    if (!v.calls.empty() && v.calls.back() < m.tree.nodes.size())  // the components of the node at work, which it calls next
        for (const std::uint32_t c : m.tree.nodes[v.calls.back()].children)
            label_node(c, c < v.marks.size() && v.marks[c] == CallMark::missed ? missed : c < v.marks.size() && v.marks[c] == CallMark::hit ? met : visited * glm::vec4(1, 1, 1, 2.5f));
    for (std::size_t node = 0; node < v.marks.size(); ++node)
        if (v.marks[node] == CallMark::skipped) label_node(std::uint32_t(node), visited * glm::vec4(1, 1, 1, 2.5f));
        else if (v.volume && v.volume->node == node && (v.calls.empty() || v.calls.back() != node))
            label_node(std::uint32_t(node), v.volume->hit ? at_work : rgba(intersection_colours::missed, 1));
}

void intersection_view_bounds(const IntersectionView& v, glm::vec3& centre, float& radius) {
    algo::Aabb b = v.input->model.tree.nodes.empty() ? algo::Aabb{} : v.input->model.tree.nodes[0].box;
    for (const algo::Ray& r : v.input->rays) b.add(r.origin);
    centre = f(b.centre());
    radius = float(glm::length(b.size()) / 2);
}

}  // namespace hsr::viz
