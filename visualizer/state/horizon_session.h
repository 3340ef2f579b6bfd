// SPDX-License-Identifier: MIT
// A floating-horizon lesson: a terrain's curves, nearest first, drawn on a screen of the lesson's grid width in
// columns, with the upper and lower horizons as they rise and sink.
#pragma once

#include <memory>

#include "horizon/floating_horizon.h"
#include "state/family_facts.h"
#include "state/session.h"

namespace hsr::viz {

struct HorizonView {
    std::shared_ptr<const algo::Terrain> terrain;
    int columns = 0;                        // screen columns (the lesson's grid width)
    std::vector<double> y;                  // screen y of every point tested so far, rows × columns
    std::vector<algo::Sight> sight;         // its verdict (where tested)
    std::vector<std::uint8_t> tested;       // 1 where the point is tested
    std::vector<double> upper, lower;       // the horizons per column (±∞ before the first curve)
    int row = -1, column = -1;              // the curve being drawn, and its point tested last (−1: none)
    std::optional<algo::PointTested> last;  // that point's test
    int curves_drawn = 0;
    std::uint64_t visible = 0, hidden = 0;
    bool done = false;
    double y_min = 0, y_max = 1;            // screen y of the whole terrain (the canvas's range)

    std::size_t at(int r, int c) const { return std::size_t(r) * std::size_t(columns) + std::size_t(c); }
};

// The lesson's terrain, nothing drawn yet.
HorizonView horizon_initial_view(const Lesson& lesson);
void reduce(HorizonView& view, const algo::HorizonEvent& event);
std::size_t approx_bytes(const HorizonView& view);

class HorizonSession : public PlayerSession<algo::HorizonEvent, algo::HorizonImage, HorizonView> {
public:
    explicit HorizonSession(Lesson lesson, PlayerOptions options = {});
    static RunType machine(const Lesson& lesson);  // the lesson's machine and the view it starts from
    static const FamilyFacts facts;  // for the presets and the report
    static bool plays(algo::HorizonMachine) { return true; }  // every HorizonMachine (state/family_contract.h)
    static std::string sentence_of(const algo::HorizonEvent& e, const HorizonView& view);  // describe(e)

private:
    std::string describe_event(const algo::HorizonEvent& e) const override;
    std::string speak_event(const algo::HorizonEvent& e) const override;
    const Pseudocode<algo::HorizonEvent>& table() const override;
};

}  // namespace hsr::viz
