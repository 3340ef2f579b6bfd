// SPDX-License-Identifier: MIT
// The compositing lesson: the window's view folds to the machine's composites, and each pseudocode line is the
// step's own.
#include "catch.h"
#include "state/composite_session.h"
#include "state/families.h"

using namespace hsr::viz;
using namespace hsr::algo;

TEST_CASE("an alpha-compositing lesson folds to the machine's composites", "[state][compositing]") {
    const Lesson lesson = load_lesson(HSR_SOURCE_DIR "/lessons/32_alpha_compositing.toml");
    auto session = make_session(lesson);
    auto* s = session.get_if<CompositeSession>();
    REQUIRE(s);
    const CompositeResult r = composite(layers_along(lesson.scene, centre_ray(lesson.scene.camera))).run_to_end();
    s->seek_end();
    const CompositeView& v = s->view();
    CHECK(v.done);
    CHECK(v.back_to_front == r.back_to_front);
    CHECK(v.front_to_back == r.front_to_back);
    CHECK(v.premultiplied.size() == v.layers->size());
    CHECK(v.over_layer == 0);  // the nearest is laid last
    REQUIRE(v.stopped);
    CHECK(v.stopped->layer == 3);
    CHECK(v.porter_duff.size() == porter_duff_operators().size());
    // stepping back undoes: before the first over, nothing is composited
    s->seek(0);
    while (!s->at_end() && s->view().premultiplied.empty()) s->step();  // premultiply layer 0
    CHECK(s->view().over_layer == -1);
    CHECK(std::string(s->pseudocode()[std::size_t(s->current_line())]).find("αr") != std::string::npos);
    while (!s->at_end() && s->view().over_layer < 0) s->step();
    CHECK(s->view().over_layer == 3);  // the farthest first
    CHECK(std::string(s->pseudocode()[std::size_t(s->current_line())]).find("over C") != std::string::npos);
}
