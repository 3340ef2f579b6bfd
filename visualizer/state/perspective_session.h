// SPDX-License-Identifier: MIT
// A perspective-transform lesson: the view volume warped into the canonical box step by step, the scene's points
// carried along with their projectors, then every pair compared for being an occluding pair before the transform
// (x/z, y/z) and after it (x′, y′).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "perspective/perspective_transform.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

// What never changes while a lesson plays: the maps the picture is drawn with and the points in eye space.
struct PerspectiveInput {
    algo::ViewVolumeMaps maps;
    std::vector<algo::Vec3> corners;  // the view volume's, eye space
    std::vector<algo::Vec3> points;   // the scene's, eye space
    double near = 1, far = 10;
};

struct PerspectiveView {
    std::shared_ptr<const PerspectiveInput> input;
    std::uint32_t stage = 0;  // the warp drawn: 0 (eye space), 1 (normalized), 2 (transformed) …
    double s = 0;             // … and how far into that stage
    std::vector<std::optional<algo::PointTransformed>> transformed;  // per point, once divided by w
    std::vector<bool> left_out;
    std::optional<algo::PairCompared> pair;  // the pair under comparison
    std::vector<std::pair<std::uint32_t, std::uint32_t>> occluding;  // found so far: nearer, farther
    std::uint64_t comparisons = 0;
    std::optional<algo::TransformFinished> finished;
};

PerspectiveView perspective_initial_view(const algo::Scene& scene);
void reduce(PerspectiveView& view, const algo::TransformEvent& event);
std::size_t approx_bytes(const PerspectiveView& view);

class PerspectiveSession : public PlayerSession<algo::TransformEvent, algo::TransformResult, PerspectiveView> {
public:
    explicit PerspectiveSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::PerspectiveMachine) { return true; }  // every PerspectiveMachine (state/family_contract.h)
    static std::string sentence_of(const algo::TransformEvent& e, const PerspectiveView& view);  // describe(e)

private:
    std::string describe_event(const algo::TransformEvent& e) const override;
    std::string speak_event(const algo::TransformEvent& e) const override;
    const Pseudocode<algo::TransformEvent>& table() const override;
};

}  // namespace hsr::viz
