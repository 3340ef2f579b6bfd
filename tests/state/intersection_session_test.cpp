// SPDX-License-Identifier: MIT
// The intersection-test lesson: the window's view folds to the machine's answers and counts.
#include "catch.h"
#include "state/families.h"
#include "state/intersection_session.h"

using namespace hsr::viz;
using namespace hsr::algo;

TEST_CASE("an intersection-test lesson folds to the machine's answers and counts", "[state][volumes]") {
    const Lesson lesson = load_lesson(HSR_SOURCE_DIR "/lessons/37_intersection_test.toml");
    auto session = make_session(lesson);
    auto* s = session.get_if<IntersectionSession>();
    REQUIRE(s);
    CHECK(lesson.volume == "kdop");
    CHECK(lesson.k == 14);
    const BoundingOptions options = bounding_options(lesson);
    CHECK(options.volume == VolumeKind::kdop);
    const IntersectionResult result = intersection_test(lesson.scene, rays_of(lesson.scene), {.bounding = options}).run_to_end();
    s->seek_end();
    const IntersectionView& v = s->view();
    REQUIRE(v.finished);
    REQUIRE(v.answers.size() == result.hits.size());
    for (std::size_t r = 0; r < v.answers.size(); ++r) CHECK(v.answers[r] == std::optional<bool>(result.hits[r] != 0));
    CHECK(v.volume_tests == result.volume_tests);
    CHECK(v.primitive_tests == result.primitive_tests);
    CHECK(v.false_alarms == result.false_alarms);
    CHECK(v.calls.empty());  // every call returned
    // the lesson's rays: a miss through the rod's void, a hit on the ball, a miss between the objects
    CHECK(result.hits == std::vector<std::uint8_t>{0, 1, 0});
    s->seek(0);
    CHECK(s->view().volume_tests == 0);
}

TEST_CASE("a lesson's volume and k are checked, with the file and line", "[state][volumes]") {
    for (const auto& [line, key] : {std::pair{"volume = \"box\"\n", "volume"}, std::pair{"k = 8\n", "k"}}) {
        const std::string text = std::string("title = \"t\"\nalgorithm = \"intersection_test\"\nscene = \"intersection_rays.toml\"\n") + line;
        try {
            (void)load_lesson_text(HSR_SOURCE_DIR "/assets/scenes/volume_test.toml", text);
            FAIL("taken: " << line);
        } catch (const std::exception& e) {
            CHECK(std::string(e.what()).find(key) != std::string::npos);
            CHECK(std::string(e.what()).find("volume_test.toml:4") != std::string::npos);
        }
    }
}
