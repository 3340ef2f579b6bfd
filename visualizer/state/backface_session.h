// SPDX-License-Identifier: MIT
// A back-face culling lesson: one of the three tests over the scene's polygons, seen from its camera.
#pragma once

#include "state/backface_view.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

class BackfaceSession : public PlayerSession<algo::CullEvent, std::vector<std::int32_t>, BackfaceView> {
public:
    explicit BackfaceSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::BackfaceTest) { return true; }  // every BackfaceTest (state/family_contract.h)
    static std::string sentence_of(const algo::CullEvent& e, const BackfaceView& view);  // describe(e), as the view after it names things

private:
    std::string describe_event(const algo::CullEvent& e) const override;
    std::string speak_event(const algo::CullEvent& e) const override;
    const Pseudocode<algo::CullEvent>& table() const override;
};

}  // namespace hsr::viz
