// SPDX-License-Identifier: MIT
// The general-forms lesson: the window's view folds to the machine's two images and visible parts.
#include "catch.h"
#include "state/families.h"
#include "state/forms_session.h"

using namespace hsr::viz;
using namespace hsr::algo;

TEST_CASE("a general-forms lesson folds to the machine's visible parts and both images", "[state][forms]") {
    const Lesson lesson = load_lesson(HSR_SOURCE_DIR "/lessons/36_object_and_image_space.toml");
    auto session = make_session(lesson);
    auto* s = session.get_if<FormsSession>();
    REQUIRE(s);
    const FormsResult result = general_forms(lesson.scene, {.pixels = std::uint32_t(lesson.grid.width)}).run_to_end();
    s->seek_end();
    const FormsView& v = s->view();
    REQUIRE(v.finished);
    CHECK(v.object_image == result.object_image);
    CHECK(v.image_image == result.image_image);
    CHECK(v.object_image == v.image_image);  // the lesson's scene: both forms draw the same row
    // the lesson's numbers: 5 of 6 walls in view, 20 comparisons, 80 tests; wall 5 hidden entirely, wall 6 not in view
    CHECK(v.finished->in_view == 5);
    CHECK(v.comparisons == 20);
    CHECK(v.tests == 16 * 5);
    REQUIRE(v.visible[4]);
    CHECK(v.visible[4]->empty());
    CHECK_FALSE(v.visible[5]);
    CHECK_FALSE(v.input->images[5]);
    // stepping back to the start folds to the first view again
    s->seek(0);
    CHECK(s->view().comparisons == 0);
    CHECK(s->view().object_image == std::vector<std::int32_t>(16, -1));
}
