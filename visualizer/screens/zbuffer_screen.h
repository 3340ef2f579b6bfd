// SPDX-License-Identifier: MIT
// The z-buffer: the fat pixels being filled (or the scene in 3D, key V); on the pixels a vertex drags at its depth,
// Shift+drag draws a triangle, a right-click deletes the polygon shown there.
#pragma once

#include "panels/zbuffer_panels.h"
#include "screens/screen.h"
#include "state/zbuffer_session.h"

namespace hsr::viz {

template <>
class Screen<ZBufferSession> : public ScreenDefaults {
public:
    void frame(const ZBufferSession& s, OrbitCamera& camera);
    void draw_scene(const ZBufferSession& s, SceneFrame& f) const;
    void draw_panels(const ZBufferSession& s, PanelFrame& f) const;
    bool pointer(const ZBufferSession& s, const Pointer& p, const ViewGeometry& g, UiActions& out);
    bool apply(ZBufferSession& s, const UiActions& a);
    std::optional<algo::Scene> edited_scene(const ZBufferSession& s) const { return s.edited_scene(); }
    glm::vec2 gesture_point(const ZBufferSession& s, glm::dvec2 pixel, const ViewGeometry& g) const;  // grid pixels

private:
    static std::optional<FatGrid> grid(const ZBufferSession& s, const ViewGeometry& g);  // none: 3D or covered
    bool dragging_ = false, drawing_ = false;
    std::pair<std::size_t, std::size_t> vertex_{0, 0};  // (polygon, vertex) being dragged
    glm::dvec2 drawing_from_{0};                         // where a Shift+drag began, in grid pixels
};

}  // namespace hsr::viz
