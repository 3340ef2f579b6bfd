// SPDX-License-Identifier: MIT
// Ray-casting lessons: the image folded from the events is the machine's, and seeking equals folding.
#include "catch.h"
#include "state/raycast_session.h"

using namespace hsr::viz;
using namespace hsr::algo;

TEST_CASE("a ray-casting lesson folds to the ray cast's image, with every acceleration", "[state][raycast]") {
    const char* id = GENERATE("raycast_brute", "raycast_grid", "raycast_octree");
    RayCastSession s(load_lesson(HSR_SOURCE_DIR "/lessons/09_ray_casting_grid.toml", std::string(id)));
    s.seek_end();
    const RayCastResult r = ray_cast(s.scene(), {.viewport = s.lesson().grid, .detail = RayDetail::ray}).run_to_end();
    INFO(id);
    CHECK(s.view().owner == r.polygon);
    CHECK(s.view().done);
    CHECK(s.view().rays == std::uint64_t(s.lesson().grid.width * s.lesson().grid.height));
    CHECK(s.view().tests <= r.tests);  // brute force tests every polygon on every ray; the others at most once
}

TEST_CASE("seeking any step of a ray-casting lesson equals folding from the start", "[state][raycast]") {
    RayCastSession s(load_lesson(HSR_SOURCE_DIR "/lessons/09_ray_casting_grid.toml"));
    RayCastSession fresh(load_lesson(HSR_SOURCE_DIR "/lessons/09_ray_casting_grid.toml"));
    s.seek_end();
    const std::size_t n = s.cursor();
    std::size_t folded = 0;
    for (std::size_t k = 0; k <= n; k += 97) {
        s.seek(k);
        for (; folded < k; ++folded) fresh.micro_step();
        INFO("step " << k);
        REQUIRE(s.view().owner == fresh.view().owner);
        REQUIRE(s.view().cells == fresh.view().cells);
        REQUIRE(s.view().nearest == fresh.view().nearest);
        REQUIRE(s.view().tests == fresh.view().tests);
    }
}
