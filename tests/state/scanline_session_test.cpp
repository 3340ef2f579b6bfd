// SPDX-License-Identifier: MIT
// Scan-line lessons: the image folded from the spans is the z-buffer's, and the active edge table empties.
#include <algorithm>

#include "catch.h"
#include "state/families.h"
#include "state/scanline_session.h"

using namespace hsr::viz;
using namespace hsr::algo;

TEST_CASE("a scan-line lesson folds to the z-buffer's image, and every edge that enters leaves", "[state][scanline]") {
    ScanLineSession s(load_lesson(HSR_SOURCE_DIR "/lessons/10_scan_line.toml"));
    s.seek_end();
    Scene scene = s.lesson().scene;
    const Viewport grid = s.lesson().grid;
    scene.camera.aspect = double(grid.width) / grid.height;
    const FrameDepth z = zbuffer_fill(project_polygons(scene, grid), zbuffer_options(scene, grid, s.lesson().depth_format)).run_to_end();
    CHECK(s.view().owner == z.polygon);
    CHECK(s.view().done);
    CHECK(s.view().spans >= std::uint64_t(grid.height));
    // edges still active at the end are those reaching the bottom row
    for (std::uint32_t e : s.view().active) CHECK((*s.view().edges)[e].end_row == grid.height);
}

TEST_CASE("seeking a scan-line lesson equals folding its events", "[state][scanline]") {
    ScanLineSession s(load_lesson(HSR_SOURCE_DIR "/lessons/10_scan_line.toml"));
    ScanLineSession fresh(load_lesson(HSR_SOURCE_DIR "/lessons/10_scan_line.toml"));
    s.seek_end();
    std::size_t folded = 0;
    for (std::size_t k = 0; k <= s.cursor(); k += 13) {
        ScanLineSession& t = s;
        t.seek(k);
        for (; folded < k; ++folded) fresh.micro_step();
        INFO("step " << k);
        REQUIRE(t.view().owner == fresh.view().owner);
        REQUIRE(t.view().active == fresh.view().active);
        REQUIRE(t.view().in == fresh.view().in);
        t.seek_end();
    }
}

TEST_CASE("a depth-sort lesson folds to the machine's order and parts", "[state][depth-sort]") {
    auto lesson = load_lesson(HSR_SOURCE_DIR "/lessons/13_depth_sort_cycle.toml");
    auto session = make_session(lesson);
    auto* s = session.get_if<DepthSortSession>();
    REQUIRE(s);
    s->seek_end();
    const DepthSortResult r = depth_sort(sort_polygons(lesson.scene)).run_to_end();
    CHECK(s->view().drawn == r.order);
    CHECK(s->view().polygons.size() == r.polygons.size());
    CHECK(s->view().list.empty());
    CHECK(s->view().splits == r.splits);
    CHECK(r.splits >= 1);  // the bars cannot be ordered whole
    for (std::size_t i = 0; i < r.polygons.size(); ++i) CHECK(s->view().polygons[i].vertices == r.polygons[i].vertices);
}

TEST_CASE("a depth-sort lesson's painting so far grows with the polygons drawn", "[state][depth-sort]") {
    DepthSortSession s(load_lesson(HSR_SOURCE_DIR "/lessons/13_depth_sort_cycle.toml"));
    const Viewport size{48, 48};
    const Image empty = painted_so_far(s.view(), size);
    CHECK(std::all_of(empty.ids.begin(), empty.ids.end(), [](SceneId id) { return id == 0; }));
    s.seek_end();
    REQUIRE_FALSE(s.view().drawn.empty());
    const Image all = painted_so_far(s.view(), size);
    CHECK(all.ids != empty.ids);
    // painting one polygon fewer changes the picture (the last one drawn is seen somewhere)
    DepthSortView fewer = s.view();
    fewer.drawn.pop_back();
    CHECK(painted_so_far(fewer, size).ids != all.ids);
}

TEST_CASE("the edge table's rows show once the machine has built it, not before (its size is lesson 31's first answer)", "[state][scanline]") {
    ScanLineSession s(load_lesson(HSR_SOURCE_DIR "/lessons/31_scan_line_classic.toml"));
    s.seek(0);
    CHECK_FALSE(s.view().table_built);
    s.micro_step();
    CHECK(s.view().table_built);  // the first event builds it
    s.seek(0);
    CHECK_FALSE(s.view().table_built);  // and stepping back takes it away
}
