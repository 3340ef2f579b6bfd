// SPDX-License-Identifier: MIT
// Cells-and-portals lessons: the pre-processing (stab trees filling the PVS matrix) and the runtime portal_render
// (the eye located, its PVS row, cells visited through narrowing frusta, polygons drawn or culled). The model, its
// cell BSP and its PVS are built once per lesson (and again when the eye is dragged into a new place: only the
// runtime reruns) and shared, read-only, by the views.
#pragma once

#include <memory>
#include <vector>

#include "portals/portal_render.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

struct PortalWorld {
    algo::CellModel model;
    algo::CellBsp bsp;
    algo::Pvs pvs;  // complete: the runtime reads it
};
std::shared_ptr<const PortalWorld> portal_world(const algo::Scene& scene);

struct PvsView {
    std::shared_ptr<const PortalWorld> world;
    std::vector<std::uint8_t> matrix;      // as filled so far
    std::int32_t source = -1;              // whose stab tree is being built
    std::vector<algo::StabNode> tree;      // that tree so far
    std::vector<std::uint32_t> sequence;   // the portals last tested
    bool found = false, blocked_in_3d = false;
    algo::Vec2 sight_point{0}, sight_direction{0};  // a plan line through the sequence (found or blocked_in_3d)
    std::uint64_t tests = 0;
    bool done = false, bounded = false;
};
void reduce(PvsView& view, const algo::PvsEvent& event);
std::size_t approx_bytes(const PvsView& view);

enum class PolygonFate : std::uint8_t { untouched, drawn, back_face, frustum };

struct PortalView {
    std::shared_ptr<const PortalWorld> world;
    algo::Camera camera;                       // the eye this run is from
    std::int32_t eye_cell = -1;
    std::vector<std::int32_t> bsp_path;
    std::vector<std::uint32_t> pvs_row;
    std::int32_t cell = -1;                    // being visited
    std::vector<algo::Plane> frustum;          // its frustum
    std::vector<std::uint8_t> visited;         // per cell
    std::vector<PolygonFate> fate;             // per polygon
    struct Narrowing {
        std::uint32_t portal;
        std::vector<algo::Vec3> visible_part;  // of the opening, through which the frustum was narrowed
        std::vector<algo::Vec3> section;       // the narrowed frustum's cross-section 1 unit ahead of the eye
    };
    std::vector<Narrowing> passed;             // on the way to the cell being visited (a stack)
    std::vector<std::uint32_t> path;           // the cells on the way (a stack)
    std::int32_t portal = -1;                  // last tested
    std::int32_t polygon = -1;                 // last drawn or culled in the cell being visited
    algo::PortalVerdict verdict = algo::PortalVerdict::passed;
    std::uint32_t drawn = 0, culled_back_face = 0, culled_frustum = 0, visits = 0, portals_passed = 0;
    bool done = false, bounded = false;
};
void reduce(PortalView& view, const algo::PortalEvent& event);
std::size_t approx_bytes(const PortalView& view);
// The polygons the views label with their ids ("polygon 915"): the one last drawn or culled in the cell being
// visited and the next one it will test, as a lesson's narration and questions name them.
std::vector<std::uint32_t> named_polygons(const PortalView& view);
// Does the frustum narrowed through this opening take in more than the opening's visible part (a bounding box on
// the screen), so that the views draw both?
bool wider_than_exact(const PortalView::Narrowing& n, const algo::Camera& camera);
// The exact narrowed frustum's cross-section 1 unit ahead of the eye: the visible part seen from the eye.
std::vector<algo::Vec3> exact_section(const PortalView::Narrowing& n, const algo::Camera& camera);

class PvsSession : public PlayerSession<algo::PvsEvent, algo::Pvs, PvsView> {
public:
    explicit PvsSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::PortalMachine m) { return m == algo::PortalMachine::pvs; }
    static std::string sentence_of(const algo::PvsEvent& e, const PvsView& view);  // describe(e) naming the cells

private:
    std::string describe_event(const algo::PvsEvent& e) const override;
    std::string speak_event(const algo::PvsEvent& e) const override;
    const Pseudocode<algo::PvsEvent>& table() const override;
};

class PortalRenderSession : public PlayerSession<algo::PortalEvent, algo::PortalRenderResult, PortalView> {
public:
    explicit PortalRenderSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::PortalMachine m) { return m != algo::PortalMachine::pvs; }  // with narrowing or bounding-box frusta
    static std::string sentence_of(const algo::PortalEvent& e, const PortalView& view);  // describe(e) naming the cells
    bool bounding_box_frusta() const { return bbox_; }
    // Stand the eye at a new plan point (keeping its height and view direction) and rerun portal_render.
    void move_eye(algo::Vec2 plan_point);

private:
    std::string describe_event(const algo::PortalEvent& e) const override;
    std::string speak_event(const algo::PortalEvent& e) const override;
    const Pseudocode<algo::PortalEvent>& table() const override;
    PlayerType make_player(const algo::Camera& camera) const;
    std::shared_ptr<const PortalWorld> world_;
    bool bbox_;
    PlayerOptions options_;
};

}  // namespace hsr::viz
