// SPDX-License-Identifier: MIT
// The Roberts lesson: the window's view folds to the machine's line drawing, and the narrated numbers are the run's.
#include "catch.h"
#include "state/families.h"
#include "state/roberts_session.h"

using namespace hsr::viz;
using namespace hsr::algo;

TEST_CASE("a Roberts lesson folds to the machine's line drawing", "[state][roberts]") {
    const Lesson lesson = load_lesson(HSR_SOURCE_DIR "/lessons/33_roberts_hidden_lines.toml");
    auto session = make_session(lesson);
    auto* s = session.get_if<RobertsSession>();
    REQUIRE(s);
    const LineDrawing d = roberts(lesson.scene).run_to_end();
    s->seek_end();
    const RobertsView& v = s->view();
    CHECK(v.done);
    REQUIRE(v.edges.size() == d.edges.size());
    for (std::size_t e = 0; e < d.edges.size(); ++e) {
        CHECK(v.edges[e].removed == d.edges[e].removed);
        CHECK(v.edges[e].hidden == d.edges[e].hidden);
    }
    // the lesson's numbers: 3 cubes, 9 back edges, 54 tests, edge 16 hidden whole
    CHECK(v.input->bodies.size() == 3);
    CHECK(v.removed == 9);
    CHECK(v.tests == 54);
    CHECK(v.drawn == 26);
    REQUIRE(v.edges[16].hidden.size() == 1);
    CHECK(v.edges[16].hidden.front() == std::pair{0.0, 1.0});
}
