// SPDX-License-Identifier: MIT
#include "frame_drawing.h"

#include "frame_panels.h"
#include "render/gl.h"
#include "render/palette.h"

namespace hsr::viz {

ViewGeometry geometry_now(const LessonPlay& lp, const Renderer& r) {
    ViewGeometry g = r.geometry;
    g.overlay_open = lp.show_presets || lp.show_keys || lp.show_report || lp.show_menu;
    g.second_view = lp.second_view;
    return g;
}

void draw_frame(LessonPlay& lp, Renderer& r, const PanelLayout& layout, float scale, UiActions& actions) {
    const float view_w = layout.width - layout.side, view_h = layout.height - layout.bottom;
    const auto px = [&](float points) { return GLsizei(points * scale); };
    glViewport(0, 0, px(layout.width), px(layout.height));
    glClearColor(palette::background.x, palette::background.y, palette::background.z, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const glm::mat4 vp = draw_frame_content(lp, r.batches, r.labels, layout, actions);  // ImGui's part, drawn later
    if (!lp.session()) return;
    glViewport(0, px(layout.bottom), px(view_w), px(view_h));  // GL's y axis points up
    r.geometry.view_projection = vp, r.geometry.width = view_w, r.geometry.height = view_h;
    const float thick = scale * lp.scale;  // lines and points grow with the type (projector, Ctrl+=)
    const glm::vec2 viewport(float(px(view_w)), float(px(view_h)));
    r.batches.faint.draw(vp, viewport, 1.5f * thick, 7.0f * thick);
    r.batches.bold.draw(vp, viewport, 3.5f * thick, 11.0f * thick);
    glViewport(0, 0, px(layout.width), px(layout.height));
}

glm::vec2 gesture_window_point(LessonPlay& lp, const Renderer& r, glm::dvec2 p) {
    const ViewGeometry g = geometry_now(lp, r);
    if (!lp.family) return g.to_window({p, 0.0});
    return lp.with_family_screen([&](auto& s, auto& screen) { return screen.gesture_point(s, p, g); });
}

}  // namespace hsr::viz
