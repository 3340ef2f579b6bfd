// SPDX-License-Identifier: MIT
// The A-buffer lesson: the window's view folds to the machine's image and lists, and the narrated numbers are the run's.
#include <bit>

#include "catch.h"
#include "state/abuffer_session.h"
#include "state/families.h"

using namespace hsr::viz;
using namespace hsr::algo;

TEST_CASE("an A-buffer lesson folds to the machine's fragment lists and image", "[state][abuffer]") {
    const Lesson lesson = load_lesson(HSR_SOURCE_DIR "/lessons/35_a_buffer.toml");
    auto session = make_session(lesson);
    auto* s = session.get_if<ABufferSession>();
    REQUIRE(s);
    CHECK(lesson.mask_size == 4);
    const ABufferImage image = a_buffer(grid_scene(lesson), lesson.grid, {.mask_size = lesson.mask_size}).run_to_end();
    s->seek_end();
    const ABufferView& v = s->view();
    CHECK(v.done);
    REQUIRE(v.rgba.size() == image.rgba.size());
    for (std::size_t k = 0; k < v.rgba.size(); ++k) {
        CHECK(v.rgba[k] == image.rgba[k]);
        REQUIRE(v.lists[k].size() == image.lists[k].size());
        for (std::size_t f = 0; f < v.lists[k].size(); ++f) {  // sorted as the machine resolved them, with the scene's colours
            CHECK(v.lists[k][f].polygon == image.lists[k][f].polygon);
            CHECK(v.lists[k][f].mask == image.lists[k][f].mask);
            CHECK(v.lists[k][f].colour == image.lists[k][f].colour);
            CHECK(v.lists[k][f].opacity == image.lists[k][f].opacity);
        }
    }
    // the lesson's numbers: 124 fragments on 79 pixels, three at (10, 4) and (9, 5), the orange adding a quarter at (9, 5)
    CHECK(v.fragments == 124);
    CHECK(v.pixels_resolved == 79);
    CHECK(v.lists[v.at(10, 4)].size() == 3);
    std::vector<Fragment> at_9_5 = image.lists[v.at(9, 5)];
    REQUIRE(at_9_5.size() == 3);
    CHECK(std::popcount(at_9_5[0].mask) == 8);
    CHECK(at_9_5[1].opacity == 0.5);
    // the one-sample image beside it is the A-buffer with a mask of 1
    CHECK(v.input->one_sample == a_buffer(grid_scene(lesson), lesson.grid, {.mask_size = 1}).run_to_end().rgba);
}

TEST_CASE("a lesson's mask must be 1, 2, 4 or 8", "[state][abuffer]") {
    const std::string text = "title = \"t\"\nalgorithm = \"a_buffer\"\nscene = \"abuffer_layers.toml\"\nmask = 3\n";
    try {
        (void)load_lesson_text(HSR_SOURCE_DIR "/assets/scenes/mask_test.toml", text);
        FAIL("a mask of 3 was taken");
    } catch (const std::exception& e) {
        CHECK(std::string(e.what()).find("mask") != std::string::npos);
        CHECK(std::string(e.what()).find("mask_test.toml:4") != std::string::npos);  // the file and line
    }
}
