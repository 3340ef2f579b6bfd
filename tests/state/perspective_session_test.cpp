// SPDX-License-Identifier: MIT
// The perspective-transform lesson: the window's view folds to the machine's answer, the picture it draws from is the
// warp the machine tells, and the narrated numbers are the run's.
#include "catch.h"
#include "state/families.h"
#include "state/perspective_session.h"

using namespace hsr::viz;
using namespace hsr::algo;

TEST_CASE("a perspective-transform lesson folds to the machine's occluding pairs", "[state][perspective]") {
    const Lesson lesson = load_lesson(HSR_SOURCE_DIR "/lessons/34_perspective_transform.toml");
    auto session = make_session(lesson);
    auto* s = session.get_if<PerspectiveSession>();
    REQUIRE(s);
    const TransformResult r = perspective_transform(lesson.scene).run_to_end();

    s->seek(7);  // after the end of stage 2: the box, the eye at infinity
    CHECK(s->view().stage == 2);
    CHECK(s->view().s == 1);
    const ViewVolumeMaps& maps = s->view().input->maps;
    CHECK_FALSE(warp(maps, s->view().stage, s->view().s, Vec3(0)).has_value());
    // P0 and P1 stand on one line parallel to z in the picture, P4 and P5 do not
    const auto picture = [&](int i) { return *warp(maps, 2, 1, s->view().input->points[std::size_t(i)]); };
    CHECK(std::abs(picture(0).x - picture(1).x) < 1e-12);
    CHECK(std::abs(picture(0).y - picture(1).y) < 1e-12);
    CHECK(std::abs(picture(4).x - picture(5).x) > 0.2);

    s->seek_end();
    const PerspectiveView& v = s->view();
    REQUIRE(v.finished);
    CHECK(v.occluding == r.occluding);
    CHECK(v.occluding == std::vector<std::pair<std::uint32_t, std::uint32_t>>{{0, 1}, {2, 3}});
    CHECK(v.comparisons == 15);
    CHECK(v.finished->divisions_before == 60);
    CHECK(v.finished->divisions_after == 18);
    for (std::size_t i = 0; i < v.transformed.size(); ++i) {
        REQUIRE(v.transformed[i]);
        CHECK(Vec3(v.transformed[i]->nx, v.transformed[i]->ny, v.transformed[i]->nz) == *r.ndc[i]);
    }
}

TEST_CASE("an orthographic scene: stage 2 has nothing to do, and equal x and y make the pair", "[state][perspective]") {
    Lesson lesson = load_lesson(HSR_SOURCE_DIR "/lessons/34_perspective_transform.toml");
    lesson.scene.camera.projection = Projection::orthographic;
    lesson.scene.camera.box[0] = -2, lesson.scene.camera.box[1] = 2, lesson.scene.camera.box[2] = -2, lesson.scene.camera.box[3] = 2;
    PerspectiveSession s(lesson);
    s.seek_end();
    const PerspectiveView& v = s.view();
    REQUIRE(v.finished);
    CHECK(v.finished->divisions_before == 0);
    // P4 and P5 (equal x and y) are a pair now; P0, P1 and P2, P3 (on one perspective ray) are not
    CHECK(v.occluding == std::vector<std::pair<std::uint32_t, std::uint32_t>>{{4, 5}});
}
