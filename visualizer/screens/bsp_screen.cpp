// SPDX-License-Identifier: MIT
#include "screens/bsp_screen.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/bsp_renderer.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

// The input vertex of a 2D lesson within a few points of (x, y), as (input, vertex).
std::optional<std::pair<std::size_t, std::size_t>> vertex_near(const BspSession& s, const ViewGeometry& g, float x, float y) {
    const auto& inputs = s.job().polygons;
    for (std::size_t i = 0; i < inputs.size(); ++i)
        for (std::size_t k = 0; k < inputs[i].vertices.size(); ++k) {
            const glm::vec4 c = g.view_projection * glm::vec4(glm::vec3(inputs[i].vertices[k]), 1);
            if (c.w <= 0) continue;
            if (glm::length(g.to_window(inputs[i].vertices[k]) - glm::vec2(x, y)) < 10) return std::pair{i, k};
        }
    return std::nullopt;
}

bool near_the_eye(const BspSession& s, const ViewGeometry& g, float x, float y) {
    const glm::vec4 c = g.view_projection * glm::vec4(glm::vec3(s.view().eye), 1);
    return c.w > 0 && glm::length(g.to_window(s.view().eye) - glm::vec2(x, y)) < 14;
}

// The input segment within a few points of (x, y), if any.
std::optional<std::size_t> segment_near(const BspSession& s, const ViewGeometry& g, float x, float y) {
    const auto& inputs = s.job().polygons;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        if (inputs[i].vertices.size() != 2) continue;
        const glm::vec2 a = g.to_window(inputs[i].vertices[0]), b = g.to_window(inputs[i].vertices[1]), p(x, y);
        const glm::vec2 ab = b - a;
        const float t = glm::dot(ab, ab) > 0 ? std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.f, 1.f) : 0.f;
        if (glm::length(p - (a + t * ab)) < 8) return i;
    }
    return std::nullopt;
}

}  // namespace

void Screen<BspSession>::frame(const BspSession& s, OrbitCamera& camera) {
    glm::vec3 centre(0);
    float radius = 1;
    bsp_view_bounds(s.view(), centre, radius);
    const glm::dvec3 from = s.lesson().scene.camera.eye - glm::dvec3(centre);
    if (s.view().two_d) {
        camera.yaw = 0, camera.pitch = 0;  // face the plane z = 0
        // the plan's walls and eye, as large as the part above the first-person strip and left of the tree allows
        // (a circle round the plan's box, framed a third further down, left it a quarter of the view on a projector)
        frame_points_in_part(camera, bsp_view_points(s.view()), {0, 1 - side_box_share, 0.62f});
        return;
    } else {
        if (glm::length(from) > 0) {  // look from where the scene's eye is, a little higher
            const glm::dvec3 d = glm::normalize(from);
            camera.yaw = float(std::atan2(d.x, d.z));
            camera.pitch = float(std::clamp(std::asin(d.y) + 0.25, -1.4, 1.4));
        }
        // the tree is in the view's right part (bsp_tree_canvas), the eye's picture at its lower left
        // (bsp_painted_canvas, its top at about 0.66 of the height at 1280×800, 0.62 on a projector)
        frame_points_in_part(camera, bsp_view_points(s.view()), {0, 1 - side_box_share, 0.62f});
        return;
    }
    frame_left_of_side_box(camera, centre, radius);  // the tree is in the view's right part (bsp_tree_canvas)
}

void Screen<BspSession>::draw_scene(const BspSession& s, SceneFrame& f) const {
    draw_bsp_view(s.view(), s.edited_scene(), f.batches, f.labels);  // edits add segments: their colours
    const std::string rule = window_strings().say(algo::term(s.stats().rule));
    f.detail = tr(f.second_view && s.view().two_d ? "bsp.detail_driving" : s.view().two_d ? "bsp.detail_2d" : "bsp.detail", {{"rule", rule}});
}

bool Screen<BspSession>::pointer(const BspSession& s, const Pointer& p, const ViewGeometry& g, UiActions& out) {
    if (p.kind == Pointer::Kind::release) {
        if (!p.right && drawing_from_ && !p.over_ui)
            if (const auto to = g.on_plane_z0(p.x, p.y)) out.add_segment = std::pair{*drawing_from_, *to};
        const bool was_ours = dragging_eye_ || dragging_input_ >= 0 || drawing_from_;
        dragging_eye_ = false, dragging_input_ = -1, drawing_from_.reset();
        return was_ours;
    }
    if (p.kind == Pointer::Kind::move) {
        if (dragging_input_ >= 0)
            if (const auto at = g.on_plane_z0(p.x, p.y)) out.move_vertex = UiActions::VertexMove{std::size_t(dragging_input_), dragging_corner_, *at};
        if (dragging_eye_) out.move_eye = g.on_plane_z0(p.x, p.y);
        return dragging_eye_ || dragging_input_ >= 0 || drawing_from_;
    }
    if (p.over_ui || !s.view().two_d) return false;  // a 3D lesson's view only orbits
    if (p.right) {
        out.delete_input = segment_near(s, g, p.x, p.y);
        return false;
    }
    dragging_eye_ = near_the_eye(s, g, p.x, p.y);
    const auto v = dragging_eye_ ? std::nullopt : vertex_near(s, g, p.x, p.y);
    dragging_input_ = v ? std::int64_t(v->first) : -1, dragging_corner_ = v ? v->second : 0;
    if (!dragging_eye_ && dragging_input_ < 0 && p.shift) drawing_from_ = g.on_plane_z0(p.x, p.y);  // on empty ground
    return dragging_eye_ || dragging_input_ >= 0 || drawing_from_;
}

bool Screen<BspSession>::apply(BspSession& s, const UiActions& a) {
    bool edited = false;
    if (a.move_vertex) s.move_vertex(a.move_vertex->input, a.move_vertex->vertex, a.move_vertex->to), edited = true;
    if (a.add_segment) edited |= s.add_segment(a.add_segment->first, a.add_segment->second);
    if (a.delete_input) edited |= s.delete_input(*a.delete_input);
    if (a.undo) edited |= s.undo();
    if (a.redo) edited |= s.redo();
    if (a.move_eye) s.move_eye(*a.move_eye), edited = true;
    if (a.forward || a.left) s.drive(a.forward, a.left), edited = true;
    if (a.bsp_order) s.set_order(*a.bsp_order), edited = true;
    if (a.bsp_splitter) s.set_splitter(*a.bsp_splitter), edited = true;
    if (a.bsp_reverse) s.reorder_inputs(BspSession::Insertion::reversed), edited = true;
    if (a.bsp_shuffle) s.reorder_inputs(BspSession::Insertion::shuffled, ++shuffles_), edited = true;
    return edited;
}

}  // namespace hsr::viz
