// SPDX-License-Identifier: MIT
// The classic scan-line lesson: its image is the z-buffer's; without the extra intersections the window shows what
// the notes' form paints, wrong only where the lesson's triangles pierce each other.
#include <algorithm>

#include "catch.h"
#include "state/scanline_session.h"

using namespace hsr::viz;
using namespace hsr::algo;

namespace {

std::vector<std::int32_t> zbuffer_owner(const Lesson& lesson) {
    const Scene scene = grid_scene(lesson);
    return zbuffer_fill(project_polygons(scene, lesson.grid), zbuffer_options(scene, lesson.grid, lesson.depth_format)).run_to_end().polygon;
}

}  // namespace

TEST_CASE("the classic scan-line lesson: the z-buffer's image, depth compared where spans begin", "[state][scanline][classic]") {
    ScanLineSession s(load_lesson(HSR_SOURCE_DIR "/lessons/31_scan_line_classic.toml"));
    REQUIRE(s.classic());
    CHECK(s.view().classic);
    const auto reference = zbuffer_owner(s.lesson());
    s.seek_end();
    CHECK(s.view().done);
    CHECK(s.view().owner == reference);
    CHECK(s.view().compared == 23);  // as the lesson's last chapter says
    CHECK(s.view().piercings == 7);
    // the pseudocode line of an extra intersection is its own
    s.seek(0);
    bool seen = false;
    while (!s.at_end() && !seen) {
        s.micro_step();
        if (s.view().piercings == 1) {
            seen = true;
            CHECK(std::string(s.pseudocode()[std::size_t(s.current_line())]).find("extra") != std::string::npos);
        }
    }
    CHECK(seen);
}

TEST_CASE("the classic scan-line lesson without its extra intersections paints the notes' form", "[state][scanline][classic]") {
    ScanLineSession s(load_lesson(HSR_SOURCE_DIR "/lessons/31_scan_line_classic.toml"));
    const auto reference = zbuffer_owner(s.lesson());
    const Viewport grid = s.lesson().grid;
    s.seek(60);
    s.set_find_piercings(false);
    CHECK_FALSE(s.finds_piercings());
    CHECK(s.cursor() == 60);  // the same step, on the rerun machine
    s.seek_end();
    CHECK(s.view().piercings == 0);
    std::vector<int> wrong_lines;
    for (int y = 0; y < grid.height; ++y)
        for (int x = 0; x < grid.width; ++x) {
            const std::size_t k = std::size_t(y) * std::size_t(grid.width) + std::size_t(x);
            if (s.view().owner[k] == reference[k]) continue;
            INFO("pixel " << x << ", " << y);
            CHECK(x >= 17);                   // past the planes' meeting, before #0's right edge
            CHECK(reference[k] == 0);         // #0 is nearer there …
            CHECK(s.view().owner[k] == 1);    // … and #1 kept its colour
            wrong_lines.push_back(y);
        }
    CHECK(wrong_lines.size() == 18);  // as the lesson says
    wrong_lines.erase(std::unique(wrong_lines.begin(), wrong_lines.end()), wrong_lines.end());
    CHECK(wrong_lines == std::vector<int>{8, 9, 10, 11, 12, 14, 15});  // line 13: #2's edge at 17.26 compares again
    s.set_find_piercings(true);
    s.seek_end();
    CHECK(s.view().owner == reference);
}
