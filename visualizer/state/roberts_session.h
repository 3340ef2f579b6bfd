// SPDX-License-Identifier: MIT
// A Roberts lesson: convex bodies drawn as lines from the scene's eye; each edge compared with every other body,
// the parts they hide removed, what is left drawn.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "roberts/hidden_lines.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

struct RobertsEdgeView {
    bool removed = false, finished = false;
    std::vector<std::pair<double, double>> hidden;  // the parts found so far (merged once finished)
};

struct RobertsView {
    std::shared_ptr<const algo::LineDrawingInput> input;  // never changed
    std::vector<RobertsEdgeView> edges;
    int edge = -1, by = -1;                       // the edge under test and the body it was last tested against
    std::optional<algo::EdgeTested> last_test;
    std::optional<algo::EdgeFinished> last_finished;
    std::uint64_t tests = 0;
    std::uint32_t removed = 0, drawn = 0;
    bool done = false;
};

RobertsView roberts_initial_view(const algo::Scene& scene);
void reduce(RobertsView& view, const algo::RobertsEvent& event);
std::size_t approx_bytes(const RobertsView& view);

class RobertsSession : public PlayerSession<algo::RobertsEvent, algo::LineDrawing, RobertsView> {
public:
    explicit RobertsSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::RobertsMachine) { return true; }  // every RobertsMachine (state/family_contract.h)
    static std::string sentence_of(const algo::RobertsEvent& e, const RobertsView& view);  // describe(e)

private:
    std::string describe_event(const algo::RobertsEvent& e) const override;
    std::string speak_event(const algo::RobertsEvent& e) const override;
    const Pseudocode<algo::RobertsEvent>& table() const override;
};

}  // namespace hsr::viz
