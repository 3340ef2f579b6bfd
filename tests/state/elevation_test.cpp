// SPDX-License-Identifier: MIT
// The elevation of lesson 26: along the row of rooms A, B, C, D, lines through the low window and the high one
// pass above the last low one, so no sightline from A reaches D; through the first two alone they pass.
#include "catch.h"
#include "portals/cell_model.h"
#include "scene/load_scene.h"
#include "state/elevation.h"

using namespace hsr::algo;
using namespace hsr::viz;

namespace {

// The portals of the run A → B → C → D (each going into the next room), in order.
std::vector<std::uint32_t> run_from_a(const CellModel& m, std::size_t length) {
    std::vector<std::uint32_t> run;
    std::uint32_t at = 0;  // cell A
    for (std::size_t k = 0; k < length; ++k)
        for (std::uint32_t p : m.cells[at].portals)
            if (m.portals[p].to == at + 1) {
                run.push_back(p), at = at + 1;
                break;
            }
    REQUIRE(run.size() == length);
    return run;
}

}  // namespace

TEST_CASE("the elevation of windows at different heights: a low, a high and a low one", "[state][portals][elevation]") {
    const CellModel m = cell_model(load_scene(HSR_SOURCE_DIR "/assets/scenes/cells_windows_3d.toml"));
    const glm::dvec2 point(0.5, 1.0), along(1, 0);  // the plan line down the middle of the row

    const auto three = elevation_of(m, run_from_a(m, 3), point, along);
    REQUIRE(three);
    REQUIRE(three->gaps.size() == 3);
    CHECK(three->gaps[0].s == Approx(1.5));  // the wall at x = 2, 1.5 from the line's point
    CHECK(three->gaps[0].bottom == Approx(0.2));
    CHECK(three->gaps[0].top == Approx(0.8));
    CHECK(three->gaps[1].bottom == Approx(2.2));
    CHECK_FALSE(three->passes());
    CHECK(three->reached == 2);
    REQUIRE(three->extremes.size() == 2);
    for (const glm::dvec2& l : three->extremes) {  // each passes the first two gaps and misses the third, above it
        for (int k = 0; k < 2; ++k) {
            const double h = l.x + l.y * three->gaps[std::size_t(k)].s;
            CHECK(h >= three->gaps[std::size_t(k)].bottom - 1e-9);
            CHECK(h <= three->gaps[std::size_t(k)].top + 1e-9);
        }
        CHECK(l.x + l.y * three->gaps[2].s > three->gaps[2].top);
    }
    // the shallowest climbs from the top of the first window to the bottom of the second: (2.2 − 0.8) / 2
    CHECK(std::min(three->extremes[0].y, three->extremes[1].y) == Approx(0.7));

    const auto two = elevation_of(m, run_from_a(m, 2), point, along);
    REQUIRE(two);
    CHECK(two->passes());

    // a slanted plan line: the distances grow by 1 / cos, the verdict stays
    const auto slanted = elevation_of(m, run_from_a(m, 3), point, glm::dvec2(1, 0.1));
    REQUIRE(slanted);
    CHECK(slanted->reached == 2);
    CHECK(slanted->gaps[0].s > three->gaps[0].s);

    // a line along the walls crosses no opening: nothing to draw
    CHECK_FALSE(elevation_of(m, run_from_a(m, 1), glm::dvec2(2, -1), glm::dvec2(0, 1)));
}
