// SPDX-License-Identifier: MIT
// A scan-line lesson: the edge table, the active edge table and in/out flags, with a one-line z-buffer, over a
// classroom-sized grid of fat pixels.
#pragma once

#include "state/scanline_view.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

class ScanLineSession : public PlayerSession<algo::ScanLineEvent, algo::FrameDepth, ScanView> {
public:
    explicit ScanLineSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static const FamilyFacts facts;  // for the presets and the report
    static std::string sentence_of(const algo::ScanLineEvent& e, const ScanView& view);  // describe(e), as the view after it names things

private:
    std::string describe_event(const algo::ScanLineEvent& e) const override;
    std::string speak_event(const algo::ScanLineEvent& e) const override;
    const Pseudocode<algo::ScanLineEvent>& table() const override;
};

}  // namespace hsr::viz
