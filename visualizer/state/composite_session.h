// SPDX-License-Identifier: MIT
// An alpha-compositing lesson: the translucent layers the ray through the image's centre passes through,
// premultiplied, composited back to front and front to back, checked for associativity, and combined by Porter and
// Duff's operators.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "compositing/compositing.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

struct CompositeView {
    std::shared_ptr<const std::vector<algo::Layer>> layers;  // nearest first, never changed
    std::vector<algo::Rgba> premultiplied;  // the layers premultiplied so far
    algo::Rgba back_to_front, straight;      // the composites so far (premultiplied; straight)
    int over_layer = -1;                     // the layer composited last back to front (−1: none yet)
    algo::Rgba front_to_back;
    int under_layer = -1;                    // … and front to back
    std::optional<algo::EarlyStop> stopped;
    std::optional<algo::OrdersCompared> compared;
    std::optional<algo::AssociativityChecked> associativity;
    std::vector<algo::PorterDuffApplied> porter_duff;
    std::optional<algo::CompositeEvent> last;  // the event last folded (the formula box shows its numbers)
    bool done = false;
};

CompositeView composite_initial_view(std::vector<algo::Layer> layers);
void reduce(CompositeView& view, const algo::CompositeEvent& event);
std::size_t approx_bytes(const CompositeView& view);

class CompositeSession : public PlayerSession<algo::CompositeEvent, algo::CompositeResult, CompositeView> {
public:
    explicit CompositeSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::CompositeMachine) { return true; }  // every CompositeMachine (state/family_contract.h)
    static std::string sentence_of(const algo::CompositeEvent& e, const CompositeView& view);  // describe(e)

private:
    std::string describe_event(const algo::CompositeEvent& e) const override;
    std::string speak_event(const algo::CompositeEvent& e) const override;
    const Pseudocode<algo::CompositeEvent>& table() const override;
};

}  // namespace hsr::viz
