// SPDX-License-Identifier: MIT
// A z-merge lesson: the scene's polygons in two parts (the first half, A, and the rest, B), each z-buffered on its
// own, then merged pixel by pixel as the lecture gives it.
#pragma once

#include <memory>

#include "state/family_facts.h"
#include "state/session.h"
#include "zbuffer/z_merge.h"

namespace hsr::viz {

struct ZMergeView {
    algo::Viewport viewport;
    std::shared_ptr<const std::vector<algo::ScreenPolygon>> polygons;  // all of them: A's, then B's
    std::shared_ptr<const algo::FrameDepth> a, b;                       // the two parts' buffers, never changed
    std::size_t b_offset = 0;            // B's polygon k is polygons[b_offset + k]
    std::vector<std::int32_t> merged;    // polygon index per pixel so far (−1 background; unmerged pixels −2)
    int x = -1, y = -1;                  // the pixel merged last
    std::uint32_t depth_a = 0, depth_b = 0;
    bool from_a = false;
    std::uint64_t from_a_count = 0, from_b_count = 0, background_count = 0;  // background: neither part has a polygon
    bool done = false;
};

// Parts A (the first half of the lesson's polygons) and B (the rest), z-buffered apart, before any merge.
ZMergeView zmerge_initial_view(const Lesson& lesson);
void reduce(ZMergeView& view, const algo::ZMergeEvent& event);
std::size_t approx_bytes(const ZMergeView& view);

class ZMergeSession : public PlayerSession<algo::ZMergeEvent, algo::FrameDepth, ZMergeView> {
public:
    explicit ZMergeSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::ZMergeMachine) { return true; }  // every ZMergeMachine (state/family_contract.h)
    static std::string sentence_of(const algo::ZMergeEvent& e, const ZMergeView& view);  // describe(e), as the view after it names things

private:
    std::string describe_event(const algo::ZMergeEvent& e) const override;
    std::string speak_event(const algo::ZMergeEvent& e) const override;
    const Pseudocode<algo::ZMergeEvent>& table() const override;
};

}  // namespace hsr::viz
