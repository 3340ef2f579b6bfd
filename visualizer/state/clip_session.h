// SPDX-License-Identifier: MIT
// A clipping lesson being played: the lesson, its machine behind a player, and what the panels ask of it.
#pragma once

#include <string>
#include <vector>

#include "clipping/clip_scene.h"
#include "state/clip_view.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

using ClipPlayer = Player<algo::ClipEvent, std::vector<algo::PrimitiveClip>, ClipView>;

class ClipSession : public PlayerSession<algo::ClipEvent, std::vector<algo::PrimitiveClip>, ClipView> {
public:
    explicit ClipSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::ClipAlgorithm) { return true; }  // every ClipAlgorithm (state/family_contract.h)
    static std::string sentence_of(const algo::ClipEvent& e, const ClipView& view);  // describe(e), as the view after it names things
    algo::ClipAlgorithm algorithm() const { return algorithm_; }
    algo::ClipSpace space() const { return view().space; }

private:
    std::string describe_event(const algo::ClipEvent& e) const override;
    std::string speak_event(const algo::ClipEvent& e) const override;
    const Pseudocode<algo::ClipEvent>& table() const override;
    algo::ClipAlgorithm algorithm_;
};

}  // namespace hsr::viz
