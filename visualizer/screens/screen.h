// SPDX-License-Identifier: MIT
// A family's screen: what the window needs of a family beyond the common panels (lesson, pseudocode, narration,
// timeline, questions). The primary template is declared and never defined, so a session type without a
// screens/<family>_screen.h that specialises Screen<S> does not compile.
//
// A screen is a thin adapter over render/ (GL line batches) and panels/ (ImGui): it frames the 3D view when a
// lesson loads, fills the 3D view and the caption (draw_scene), draws its canvases and state panel (draw_panels),
// and, where the family has them, turns mouse gestures into UiActions and carries those edits out.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "panels/lesson_panels.h"
#include "panels/ui_actions.h"
#include "panels/view_side_box.h"
#include "render/label.h"
#include "render/line_batch.h"
#include "render/orbit_camera.h"
#include "scene/scene.h"

namespace hsr::viz {

template <class S>
class Screen;

// The 3D view as last drawn: for picking and for scripted gestures given in world coordinates.
struct ViewGeometry {
    glm::mat4 view_projection{1};
    float width = 1, height = 1;   // of the 3D view, in window points (it starts at the window's top left)
    bool overlay_open = false;     // keys, presets or the report cover the view
    bool second_view = false;      // the family's other view is shown (key V)

    glm::vec2 to_window(const glm::dvec3& world) const;
    std::optional<glm::dvec3> on_plane_z0(float x, float y) const;  // the view's ray through (x, y) meets z = 0
};

// What draw_scene fills in before the 3D view is drawn.
struct SceneFrame {
    LineBatches& batches;
    std::vector<Label>& labels;
    std::string detail;                        // the caption under the lesson's title
    std::optional<glm::mat4> view_projection;  // a camera of the screen's own for the 3D view (else the orbit camera)
    bool second_view = false;
    float view_w = 1, view_h = 1;              // the 3D view's size
    float aspect() const { return view_w / view_h; }
    std::vector<ViewRect> covered;             // parts of the view the screen's canvases draw over: labels keep off
    glm::vec3 camera_eye{0, 0, 0};             // where the orbit camera looks from: which faces it sees from behind
};

// What draw_panels draws into, after the 3D view.
struct PanelFrame {
    float view_w, view_h;  // the 3D view's size: the canvases cover it
    const PanelLayout& layout;
    bool second_view = false;
    bool animate = true;   // tween between steps (off for screenshots and recordings)
    UiActions& actions;
};

// A press, drag or release of a mouse button, in window points.
struct Pointer {
    enum class Kind { press, move, release } kind;
    bool right = false;     // the right button (else the left)
    bool shift = false;
    bool over_ui = false;   // over an ImGui window (the fat-pixel canvas is one)
    float x = 0, y = 0;
};

// What most screens do, for them to inherit: no gestures, no edits, no tween, a world point through the 3D view.
struct ScreenDefaults {
    template <class S>
    bool pointer(const S&, const Pointer&, const ViewGeometry&, UiActions&) {
        return false;  // true: the screen took the press (no orbiting)
    }
    template <class S>
    bool apply(S&, const UiActions&) {
        return false;  // true: the machine reran on edited inputs
    }
    template <class S>
    std::optional<algo::Scene> edited_scene(const S&) const {
        return std::nullopt;  // what S saves
    }
    template <class S>
    void before_step(const S&) {}  // a step may be taken: remember what is shown, to slide from it
    template <class S>
    void after_step(const S&, bool moved, double dt) {
        (void)moved, (void)dt;
    }
    template <class S>
    glm::vec2 gesture_point(const S&, glm::dvec2 p, const ViewGeometry& g) const {
        return g.to_window({p, 0.0});  // scripted gestures name points of the plane z = 0
    }
    template <class S>
    bool drives(const S&, bool second_view) const {
        (void)second_view;
        return false;  // true: the arrow keys move the eye (UiActions::forward, left) instead of stepping
    }
    template <class S>
    bool walking(const S&) const {
        return false;  // true: the arrows walk through the scene (a screen's own walk), not step nor show the whole run
    }
    template <class S>
    bool two_d(const S&) const {
        return false;  // a 2D lesson (its random scenes are 2D too)
    }
};

// Where a lesson's scene sits, for the orbit camera to frame it.
void frame_bounds(OrbitCamera& camera, glm::vec3 centre, float radius);
// The same, left of a box in the view's right part (panels/view_side_box.h: the lesson's result, a tree or a table):
// the target moves to the camera's right and the scene is framed a little smaller (for a view about 1.1 times as
// wide as it is tall).
void frame_left_of_side_box(OrbitCamera& camera, glm::vec3 centre, float radius, float share = side_box_share);
// The same, above a box across the view's foot taking `share` of its height (begin_view_foot_box).
void frame_above_foot_box(OrbitCamera& camera, glm::vec3 centre, float radius, float share);
// A part of the view, in fractions of its width (from the left) and height (from the top): the part a scene has
// beside the boxes drawn over the view.
struct ViewPart {
    float left = 0, right = 1, bottom = 1;
};
// The sphere framed in that part of the view.
void frame_in_part(OrbitCamera& camera, glm::vec3 centre, float radius, ViewPart part);
// The points framed in that part as the camera (its yaw and pitch set) sees them: as large as their extent across
// and up the picture allows, not a sphere around them (a scene with its eye far behind it fills the part).
void frame_points_in_part(OrbitCamera& camera, const std::vector<glm::vec3>& points, ViewPart part);

}  // namespace hsr::viz
