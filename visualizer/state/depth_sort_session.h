// SPDX-License-Identifier: MIT
// A depth-sort lesson: the display list as it is sorted, the pair under examination with each test tried, moves,
// cycles and splits, and the polygons drawn back to front.
#pragma once

#include <vector>

#include "depth_sort/depth_sort.h"
#include "raster/image.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

struct DepthSortView {
    std::vector<algo::SortPolygon> polygons;  // the working list's polygons (NDC), parts appended as they are made
    std::vector<std::uint32_t> list;          // still to draw, the head first
    std::vector<std::uint32_t> drawn;         // back to front
    int r = -1, q = -1;                       // the pair under examination
    std::vector<algo::TestTried> tests;       // tried on it so far, in order
    int moved = -1, cycle = -1, cut = -1;     // what the last step did
    std::uint32_t splits = 0, moves = 0;
    bool done = false, bounded = false;
    // the display step front to back, when the lesson asks for it: drawn nearest first, each pixel once
    std::vector<std::uint32_t> front;
    std::uint32_t unwritten = 0, left = 0;  // pixels still unwritten; polygons never drawn once the screen filled
    bool screen_filled = false, front_to_back = false;
};

void reduce(DepthSortView& view, const algo::DepthSortEvent& event);
// The image the drawn polygons make so far, each painted "over" what is there, at `size` pixels (x, y in [-1, 1]).
algo::Image painted_so_far(const DepthSortView& view, algo::Viewport size);
std::size_t approx_bytes(const DepthSortView& view);

class DepthSortSession : public PlayerSession<algo::DepthSortEvent, algo::DepthSortResult, DepthSortView> {
public:
    explicit DepthSortSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::DepthSortMachine) { return true; }  // every DepthSortMachine (state/family_contract.h)
    static std::string sentence_of(const algo::DepthSortEvent& e, const DepthSortView& view);  // describe(e), as the view after it names things

private:
    std::string describe_event(const algo::DepthSortEvent& e) const override;
    std::string speak_event(const algo::DepthSortEvent& e) const override;
    const Pseudocode<algo::DepthSortEvent>& table() const override;
};

}  // namespace hsr::viz
