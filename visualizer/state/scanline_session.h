// SPDX-License-Identifier: MIT
// A scan-line lesson over a classroom-sized grid of fat pixels: the edge table, the active edge table and in/out
// flags, with a one-line z-buffer (scan_line) or, as the Brown notes give it, with the polygon table's plane
// equations compared only where spans begin (scan_line_classic).
#pragma once

#include "state/scanline_view.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

class ScanLineSession : public PlayerSession<algo::ScanLineEvent, algo::FrameDepth, ScanView> {
public:
    explicit ScanLineSession(Lesson lesson, PlayerOptions options = {});
    // the lesson's machine and the view it starts from; the classic one with or without the extra intersections
    // where polygons pierce each other
    static RunType machine(const Lesson& lesson, bool find_piercings = true);
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::ScanLineMachine) { return true; }  // every ScanLineMachine (state/family_contract.h)
    static std::string sentence_of(const algo::ScanLineEvent& e, const ScanView& view);  // describe(e), as the view after it names things

    bool classic() const { return machine_of<algo::ScanLineMachine>(lesson()) == algo::ScanLineMachine::classic; }
    bool finds_piercings() const { return find_piercings_; }
    // The classic machine again, with or without the extra intersections, at the same step where it still exists.
    void set_find_piercings(bool on);

private:
    PlayerOptions options_;
    bool find_piercings_ = true;
    std::string describe_event(const algo::ScanLineEvent& e) const override;
    std::string speak_event(const algo::ScanLineEvent& e) const override;
    const Pseudocode<algo::ScanLineEvent>& table() const override;
};

}  // namespace hsr::viz
