// SPDX-License-Identifier: MIT
// A ray-casting lesson: the lecture's RayCasting over a classroom-sized grid of fat pixels, ray by ray, with every
// primitive (raycast_brute), a regular grid walked cell by cell (raycast_grid) or an octree (raycast_octree).
#pragma once

#include "state/raycast_view.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

class RayCastSession : public PlayerSession<algo::RayCastEvent, algo::RayCastResult, RayView> {
public:
    explicit RayCastSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::Acceleration) { return true; }  // every Acceleration (state/family_contract.h)
    static std::string sentence_of(const algo::RayCastEvent& e, const RayView& view);  // describe(e), as the view after it names things
    const algo::Scene& scene() const { return scene_; }  // the lesson's, with the grid's aspect
    const algo::OctreeOptions& octree_options() const { return lesson().octree; }
    // The voxel of the octree's stopping rule: the lesson's, or the cell max_depth halvings below the root.
    double octree_voxel() const;

private:
    std::string describe_event(const algo::RayCastEvent& e) const override;
    std::string speak_event(const algo::RayCastEvent& e) const override;
    const Pseudocode<algo::RayCastEvent>& table() const override;
    bool is_major(const algo::RayCastEvent& e) const override;

    algo::Scene scene_;
};

}  // namespace hsr::viz
