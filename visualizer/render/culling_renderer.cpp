// SPDX-License-Identifier: MIT
#include "render/culling_renderer.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/frustum.h"
#include "render/palette.h"
#include "state/state_colours.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

glm::vec4 with_alpha(const StateColour& c, float alpha) { return {c.r, c.g, c.b, alpha}; }

glm::vec4 mark_colour(NodeMark m) {
    switch (m) {
        case NodeMark::outside: return with_alpha(culling_colours::outside, 0.9f);
        case NodeMark::inside: return with_alpha(culling_colours::inside, 0.9f);
        case NodeMark::partial: return with_alpha(culling_colours::partial, 0.8f);
        case NodeMark::too_small: return with_alpha(culling_colours::too_small, 0.9f);
        case NodeMark::large_enough: return with_alpha(culling_colours::large_enough, 0.8f);
        case NodeMark::occluded: return with_alpha(culling_colours::occluded, 0.9f);
        case NodeMark::visible: return with_alpha(culling_colours::visible, 0.9f);
        case NodeMark::built: return with_alpha(culling_colours::built, 0.6f);
        case NodeMark::untouched: break;
    }
    return {0, 0, 0, 0};
}

void box_lines(LineBatch& out, const algo::Aabb& b, glm::vec4 c) {
    for (int i = 0; i < 8; ++i)
        for (int axis = 1; axis < 8; axis <<= 1)
            if (!(i & axis)) out.line(glm::vec3(b.corner(i)), glm::vec3(b.corner(i | axis)), c);
}

}  // namespace

void culling_view_bounds(const CullingView& v, glm::vec3& centre, float& radius) {
    algo::Aabb all;
    for (const auto& b : v.world->hierarchy.boxes) all.add(b);
    all.add(v.world->scene.camera.eye);
    centre = glm::vec3(all.centre());
    radius = std::max(1.0f, float(glm::length(all.size()) / 2));
}

void draw_culling_view(const CullingView& v, LineBatches& out, std::vector<Label>& labels) {
    const auto& scene = v.world->scene;
    const auto& h = v.world->hierarchy;
    // the view frustum in grey, not the yellow of "partly inside" (state/state_colours.h: culling_colours::frustum)
    draw_frustum(scene.camera, out.faint, {culling_colours::frustum.r, culling_colours::frustum.g, culling_colours::frustum.b, 1.0f});
    out.bold.point(glm::vec3(scene.camera.eye), palette::eye);
    labels.push_back({glm::vec3(scene.camera.eye), tr("view.eye"), palette::eye});
    // primitives: kept solid, left out faint, not yet decided as outlines
    const bool many = scene.polygons.size() > 20000;
    for (std::size_t i = 0; i < scene.polygons.size(); ++i) {
        const auto& p = scene.polygons[i];
        const glm::vec4 c(p.color.r / 255.f, p.color.g / 255.f, p.color.b / 255.f, 1);
        const PrimitiveMark m = v.primitives[i];
        if (m == PrimitiveMark::kept)
            for (std::size_t k = 1; k + 1 < p.vertices.size(); ++k)
                out.faint.triangle(glm::vec3(p.vertices[0]), glm::vec3(p.vertices[k]), glm::vec3(p.vertices[k + 1]), c * glm::vec4(1, 1, 1, 0.85f));
        else if (!many)
            for (std::size_t k = 0; k < p.vertices.size(); ++k)
                out.faint.line(glm::vec3(p.vertices[k]), glm::vec3(p.vertices[(k + 1) % p.vertices.size()]),
                               c * glm::vec4(1, 1, 1, m == PrimitiveMark::left_out || m == PrimitiveMark::earlier ? 0.12f : 0.35f));
    }
    // the hierarchy's boxes, by what happened to them (state/culling_session.h, shown_boxes): the node under test
    // bold, its way down from the root in full colour, what is settled beside that way faint, the children still to
    // test white; the boxes the narration names labelled with their number
    const std::vector<ShownBox> boxes = shown_boxes(v);
    for (const ShownBox& b : boxes) {
        const algo::Aabb& box = h.nodes[b.node].box;
        const glm::vec4 c = b.mark == NodeMark::untouched ? with_alpha(culling_colours::built, 0.85f) : mark_colour(b.mark);
        // a build's boxes are all white ("built"): its way down fainter than the children the split made
        const float path_alpha = b.mark == NodeMark::built ? 0.4f : 1.0f;
        switch (b.weight) {
            case ShownBox::Weight::current: box_lines(out.bold, box, c); break;
            case ShownBox::Weight::path: box_lines(out.faint, box, c * glm::vec4(1, 1, 1, path_alpha)); break;
            case ShownBox::Weight::next: box_lines(out.faint, box, c); break;
            case ShownBox::Weight::settled: box_lines(out.faint, box, c * glm::vec4(1, 1, 1, v.done ? 0.45f : 0.3f)); break;
        }
    }
    for (const bool current : {false, true})  // the node under test last: its label is placed first
        for (const ShownBox& b : boxes)
            if (b.labelled && (b.weight == ShownBox::Weight::current) == current) {
                const glm::vec4 c = b.mark == NodeMark::untouched ? with_alpha(culling_colours::built, 1) : mark_colour(b.mark);
                // an octree's cells round the eye share their centres, not their tops: the middle of the top face
                const algo::Aabb& box = h.nodes[b.node].box;
                const glm::vec3 at = h.kind == algo::HierarchyKind::octree ? glm::vec3(box.centre().x, box.hi.y, box.centre().z) : glm::vec3(box.centre());
                labels.push_back({at, tr(b.node == 0 ? "culling.label_root" : "culling.label_node", {{"n", std::to_string(b.node)}}), c});
            }
    // the primitives the narration and the questions name, by their numbers; a planar occluder that is one of them
    // carries both names in one label (two labels on one face piled up at the walls' seam)
    std::vector<std::uint32_t> named = named_primitives(v);
    std::vector<std::uint8_t> named_with_occluder(scene.polygons.size(), 0);
    for (const auto& o : v.occluders)
        if (o.shape == algo::OccluderKind::planar && std::find(named.begin(), named.end(), o.polygon) != named.end())
            named_with_occluder[o.polygon] = 1;
    for (std::uint32_t p : named) {
        if (named_with_occluder[p]) continue;
        glm::dvec4 sum(0);  // the mean of its corners (homogeneous, w = 1)
        for (const auto& q : scene.polygons[p].vertices) sum += q;
        labels.push_back({glm::vec3(sum / double(scene.polygons[p].vertices.size())), "#" + std::to_string(p), palette::working});
    }
    // occluders and the rays of their occlusion frusta
    // (a proxy is the polygon square to the view that stands for a polygon or a solid; a solid's is drawn with its
    // silhouette rays, which bound what it hides)
    const algo::ViewPlane view = algo::ViewPlane::of(scene.camera);
    for (std::size_t k = 0; k < v.occluders.size(); ++k) {
        const auto& o = v.occluders[k];
        for (std::size_t i = 0; i < o.outline.size(); ++i) {
            const glm::vec3 a(o.outline[i]), b(o.outline[(i + 1) % o.outline.size()]);
            out.bold.line(a, b, palette::intersection);
            // the frustum's edge: away from the eye, or along the view for an orthographic camera
            const glm::vec3 away = view.orthographic ? glm::vec3(view.direction) * glm::length(a - glm::vec3(scene.camera.eye)) : a - glm::vec3(scene.camera.eye);
            out.faint.line(a, a + away * 1.5f, {0.9f, 0.62f, 0.0f, 0.5f});
        }
        const char* key = o.shape == algo::OccluderKind::solid ? "culling.label_solid" : o.shape == algo::OccluderKind::proxy ? "culling.label_proxy" : "culling.label_occluder";
        // numbered from 0, as the machine's sentences number them
        std::string name = tr(key, {{"n", std::to_string(k)}});
        if (o.shape == algo::OccluderKind::planar && named_with_occluder[o.polygon]) name += " = #" + std::to_string(o.polygon);
        labels.push_back({glm::vec3(algo::centroid(o.outline)), name, palette::intersection});
    }
}

void draw_walk_view(const Walkthrough& walk, LineBatches& out) {
    const auto& polygons = walk.scene().polygons;
    const auto& kept = walk.last().kept;
    for (std::size_t i = 0; i < polygons.size() && i < kept.size(); ++i) {
        if (!kept[i]) continue;
        const auto& p = polygons[i];
        // flat colours, shaded a little by the face's turn to a light above and behind the eye: walls that meet at a
        // corner stay apart
        float shade = 1;
        if (p.vertices.size() >= 3) {
            const glm::vec3 n = glm::cross(glm::vec3(p.vertices[1] - p.vertices[0]), glm::vec3(p.vertices[2] - p.vertices[0]));
            if (glm::length(n) > 0) shade = 0.65f + 0.35f * std::abs(glm::dot(glm::normalize(n), glm::normalize(glm::vec3(0.4f, 0.8f, 0.45f))));
        }
        const glm::vec4 c(shade * p.color.r / 255.f, shade * p.color.g / 255.f, shade * p.color.b / 255.f, 1);
        for (std::size_t k = 1; k + 1 < p.vertices.size(); ++k)
            out.faint.solid_triangle(glm::vec3(p.vertices[0]), glm::vec3(p.vertices[k]), glm::vec3(p.vertices[k + 1]), c);
    }
}

}  // namespace hsr::viz
