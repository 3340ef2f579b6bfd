// SPDX-License-Identifier: MIT
// A z-buffer lesson: the fill over a classroom-sized grid of fat pixels, with the depth format, near and far the
// user can change (the machine reruns; the step stays).
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "state/edit_history.h"
#include "state/family_facts.h"
#include "state/session.h"
#include "state/zbuffer_view.h"

namespace hsr::viz {

class ZBufferSession : public PlayerSession<algo::ZBufferEvent, algo::FrameDepth, ZView> {
public:
    explicit ZBufferSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::ZBufferMachine) { return true; }  // every ZBufferMachine (state/family_contract.h)
    static std::string sentence_of(const algo::ZBufferEvent& e, const ZView& view);  // describe(e)

    algo::DepthFormat format() const { return view().format; }
    algo::DepthRange range() const { return view().range; }
    void set_format(algo::DepthFormat f);
    void set_range(algo::DepthRange r);  // near and far of the camera; ignored unless 0 < near < far
    // Pixels where the image differs from the double-precision ray cast through the same centres (z-fighting,
    // mostly), for the finished fill.
    std::size_t pixels_unlike_ray_cast() const { return unlike_ray_cast_; }
    // Of those, the pixels whose centre lies exactly on an edge of the polygon the fill or the ray cast shows there:
    // a tie the fill rule settles one way and the ray cast (which counts an edge as inside) may settle the other.
    std::size_t unlike_on_edges() const { return unlike_on_edges_; }

    // Editing the scene in the fat-pixel view, each edit rerunning the fill at the same step: a vertex moved to a
    // point of the screen (pixels, x right and y down) at the window depth it had, a polygon deleted, a triangle
    // added at the depth of the scene's middle; undo and redo. An edit that would leave a polygon concave, or
    // nothing at all, is refused (false).
    bool move_vertex(std::size_t polygon, std::size_t vertex, glm::dvec2 pixel);
    bool delete_polygon(std::size_t polygon);
    bool add_triangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c);
    bool undo();
    bool redo();
    const algo::Scene& edited_scene() const { return scene_; }
    // Where a scene vertex lands: pixels (x, y) and window depth; nullopt behind the eye.
    std::optional<glm::dvec3> on_screen(const glm::dvec4& world) const;

private:
    std::string describe_event(const algo::ZBufferEvent& e) const override;
    std::string speak_event(const algo::ZBufferEvent& e) const override;
    const Pseudocode<algo::ZBufferEvent>& table() const override;
    void rerun();
    bool edit(algo::Scene edited, std::optional<std::pair<std::size_t, std::size_t>> moved = std::nullopt);
    glm::dvec4 world_at(glm::dvec2 pixel, double depth) const;  // the inverse of on_screen

    algo::Scene scene_;  // the lesson's, with the near and far the user chose
    algo::DepthFormat format_;
    PlayerOptions options_;
    std::size_t unlike_ray_cast_ = 0, unlike_on_edges_ = 0;
    EditHistory<algo::Scene> history_;
    std::optional<std::pair<std::size_t, std::size_t>> last_moved_;  // a drag is one undo step
};

}  // namespace hsr::viz
