// SPDX-License-Identifier: MIT
#include "screens/zbuffer_screen.h"

#include <cmath>

#include "render/frustum.h"
#include "render/zbuffer_renderer.h"
#include "state/strings.h"

namespace hsr::viz {
namespace {

// The scene vertex within a few points of (x, y) on the grid, as (polygon, vertex).
std::optional<std::pair<std::size_t, std::size_t>> vertex_near(const ZBufferSession& s, const FatGrid& g, float x, float y) {
    const auto& polygons = s.edited_scene().polygons;
    for (std::size_t i = 0; i < polygons.size(); ++i)
        for (std::size_t k = 0; k < polygons[i].vertices.size(); ++k)
            if (const auto p = s.on_screen(polygons[i].vertices[k]))
                if (std::hypot(g.x0 + float(p->x) * g.cell - x, g.y0 + float(p->y) * g.cell - y) < 10) return std::pair{i, k};
    return std::nullopt;
}

}  // namespace

void Screen<ZBufferSession>::frame(const ZBufferSession& s, OrbitCamera& camera) {
    glm::vec3 centre(0);
    float radius = 1;
    scene_bounds(s.lesson().scene, centre, radius);
    frame_bounds(camera, centre, radius);
}

void Screen<ZBufferSession>::draw_scene(const ZBufferSession& s, SceneFrame& f) const {
    if (f.second_view) draw_zbuffer_3d(s.view(), s.lesson().scene, f.batches, f.labels);
    f.detail = tr("zbuffer.caption", {{"width", std::to_string(s.lesson().grid.width)}, {"height", std::to_string(s.lesson().grid.height)},
                                      {"format", window_strings().name(algo::to_string(s.format()))}});
}

void Screen<ZBufferSession>::draw_panels(const ZBufferSession& s, PanelFrame& f) const {
    if (!f.second_view) zbuffer_canvas(s, 0, 0, f.view_w, f.view_h);
    zbuffer_state_panel(s, f.second_view, f.layout, f.actions);
}

std::optional<FatGrid> Screen<ZBufferSession>::grid(const ZBufferSession& s, const ViewGeometry& g) {
    if (g.second_view || g.overlay_open) return std::nullopt;
    return zbuffer_frame_grid(s, 0, 0, g.width, g.height);
}

glm::vec2 Screen<ZBufferSession>::gesture_point(const ZBufferSession& s, glm::dvec2 pixel, const ViewGeometry& g) const {
    const auto fat = grid(s, g);
    if (!fat) return g.to_window({pixel, 0.0});
    return {fat->x0 + float(pixel.x) * fat->cell, fat->y0 + float(pixel.y) * fat->cell};
}

bool Screen<ZBufferSession>::pointer(const ZBufferSession& s, const Pointer& p, const ViewGeometry& g, UiActions& out) {
    const auto fat = grid(s, g);
    if (!fat) return false;
    const glm::dvec2 at((p.x - fat->x0) / fat->cell, (p.y - fat->y0) / fat->cell);  // in grid pixels
    const bool on_grid = at.x >= 0 && at.y >= 0 && at.x < s.lesson().grid.width && at.y < s.lesson().grid.height;
    switch (p.kind) {
        case Pointer::Kind::press:
            if (p.right) {
                if (!on_grid) return false;
                const auto owner = s.view().owner[std::size_t(int(at.y)) * std::size_t(s.lesson().grid.width) + std::size_t(int(at.x))];
                if (owner >= 0) out.delete_polygon = std::size_t(owner);
                return true;
            } else {
                const auto near = vertex_near(s, *fat, p.x, p.y);
                dragging_ = near.has_value();
                if (near) vertex_ = *near;
                drawing_ = !dragging_ && p.shift && on_grid;
                drawing_from_ = at;
                return dragging_ || drawing_;
            }
        case Pointer::Kind::move:
            if (dragging_) out.move_screen_vertex = UiActions::ScreenVertexMove{vertex_.first, vertex_.second, at};
            return dragging_;
        case Pointer::Kind::release:
            if (!p.right && drawing_) out.add_triangle = std::array{drawing_from_, glm::dvec2(at.x, drawing_from_.y), at};
            const bool was_ours = dragging_ || drawing_;
            dragging_ = drawing_ = false;
            return was_ours;
    }
    return false;
}

bool Screen<ZBufferSession>::apply(ZBufferSession& s, const UiActions& a) {
    if (a.depth_format) s.set_format(*a.depth_format);
    if (a.depth_range) s.set_range(*a.depth_range);
    bool edited = false;
    if (a.move_screen_vertex) edited |= s.move_vertex(a.move_screen_vertex->polygon, a.move_screen_vertex->vertex, a.move_screen_vertex->pixel);
    if (a.add_triangle) edited |= s.add_triangle((*a.add_triangle)[0], (*a.add_triangle)[1], (*a.add_triangle)[2]);
    if (a.delete_polygon) edited |= s.delete_polygon(*a.delete_polygon);
    if (a.undo) edited |= s.undo();
    if (a.redo) edited |= s.redo();
    return edited;
}

}  // namespace hsr::viz
