// SPDX-License-Identifier: MIT
// Walking through a culling scene (state/walkthrough.h): the eye walks on the level and turns as the keys say, a
// drag looks around within its limits, a frame is made again only after a change, and every frame of a walk, with
// any stages switched on, Hi-Z's frame-to-frame coherence or not, loses no front-face pixel against the frame that
// draws every primitive from the same eye. A floor plan walks with its portals stage; outside every room the walk
// says why it has no frame instead of failing.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "catch.h"
#include "analysis/lost_pixels.h"
#include "scene/generated_scenes.h"
#include "scene/load_scene.h"
#include "state/walkthrough.h"

using namespace hsr::viz;
using namespace hsr::algo;

namespace {

Vec3 heading(const Camera& c) { return glm::normalize(c.target - c.eye); }

// The moves of a walk through the city: forward, a turn, a look up and down, back.
void move(Walkthrough& w, int k) {
    switch (k % 6) {
        case 0: case 1: w.walk(1, 0); break;
        case 2: w.walk(0, 1); break;
        case 3: w.look(40, 10); break;
        case 4: w.walk(1, -1); break;
        default: w.look(-25, -10); break;
    }
}

}  // namespace

TEST_CASE("the walk: a step forward on the level, a turn, a look within its limits", "[state][walk]") {
    const Scene city = city_scene({.triangles = 600});
    Walkthrough w(city, {Stage::frustum}, {64, 48});
    const Camera start = w.camera();
    const Vec3 h = heading(start);
    w.walk(1, 0);
    const Vec3 moved = w.camera().eye - start.eye;
    CHECK(moved.y == 0);  // on the level
    CHECK(glm::length(moved) > 0);
    const Vec3 level = glm::normalize(Vec3(h.x, 0, h.z));
    CHECK(glm::dot(glm::normalize(moved), level) == Approx(1));  // along the heading
    w.walk(-1, 0);
    CHECK(glm::length(w.camera().eye - start.eye) < 1e-9);  // and back
    w.walk(0, 1);  // a turn to the left: the heading swings from the right vector towards the left
    const Vec3 right = glm::normalize(glm::cross(h, Vec3(0, 1, 0)));
    CHECK(glm::dot(heading(w.camera()), right) < 0);
    CHECK(std::acos(std::clamp(glm::dot(glm::normalize(Vec3(heading(w.camera()).x, 0, heading(w.camera()).z)), level), -1.0, 1.0)) ==
          Approx(5.0 * M_PI / 180));
    w.look(0, 100000);  // far down: stops short of straight down
    CHECK(heading(w.camera()).y == Approx(-std::sin(80.0 * M_PI / 180)));
    w.look(0, -200000);
    CHECK(heading(w.camera()).y == Approx(std::sin(80.0 * M_PI / 180)));
}

TEST_CASE("a frame is made again only after a move or a switch, and a switch takes its stage out", "[state][walk]") {
    Walkthrough w(city_scene({.triangles = 600}), {Stage::back_face, Stage::frustum}, {64, 48});
    (void)w.frame();
    (void)w.frame();
    CHECK(w.frames() == 1);
    const auto report = [&](Stage s) {
        const auto& st = w.last().stages;
        return *std::find_if(st.begin(), st.end(), [&](const StageReport& r) { return r.stage == s; });
    };
    CHECK(report(Stage::frustum).ran);
    CHECK(report(Stage::frustum).left_out > 0);
    w.toggle(Stage::frustum);
    (void)w.frame();
    CHECK(w.frames() == 2);
    CHECK_FALSE(w.on(Stage::frustum));
    CHECK_FALSE(report(Stage::frustum).ran);
    CHECK(report(Stage::frustum).in == report(Stage::frustum).passed);
    w.toggle(Stage::hse);  // hidden-surface elimination always runs
    CHECK(w.on(Stage::hse));
    const auto stages = w.switchable();
    CHECK(std::find(stages.begin(), stages.end(), Stage::portals) == stages.end());  // no floor plan here
    CHECK(w.summary().find("back-face") != std::string::npos);
}

TEST_CASE("every frame of a walk through the city loses no front-face pixel, coherent Hi-Z or not", "[state][walk]") {
    const Scene city = city_scene({.triangles = 3000, .seed = 4});
    const Viewport vp{96, 72};
    const std::vector<Stage> all = {Stage::back_face, Stage::frustum, Stage::occluders, Stage::hiz};
    Walkthrough culled(city, all, vp, {.occluders = OccluderKind::solid, .fusion = true});
    Walkthrough coherent(city, all, vp);
    coherent.set_coherent(true);
    Walkthrough every(city, {}, vp);
    std::uint64_t left_out = 0, drawn_first = 0;
    for (int k = 0; k < 14; ++k) {
        INFO("frame " << k);
        const PipelineResult& a = culled.frame();
        const PipelineResult& b = coherent.frame();
        const PipelineResult& c = every.frame();
        REQUIRE(culled.error().empty());
        CHECK(hsr::analysis::lost_front_pixels(culled.scene(), a.frame, c.frame) == 0);
        CHECK(hsr::analysis::lost_front_pixels(coherent.scene(), b.frame, c.frame) == 0);
        for (const StageReport& r : a.stages) left_out += r.stage == Stage::hse ? 0 : r.left_out;
        if (k > 0) drawn_first += coherent.drawn_first();
        move(culled, k), move(coherent, k), move(every, k);
    }
    CHECK(left_out > 0);
    CHECK(drawn_first > 0);  // each frame after the first drew the last one's view first
    CHECK(culled.frames() == 14);
}

TEST_CASE("a floor plan walks with its portals stage, and outside every room the walk says why it has no frame", "[state][walk]") {
    const Scene plan = load_scene(HSR_SOURCE_DIR "/assets/scenes/cells_lecture.toml");
    Walkthrough w(plan, {Stage::portals}, {64, 48});
    Walkthrough every(plan, {}, {64, 48});
    const auto stages = w.switchable();
    CHECK(std::find(stages.begin(), stages.end(), Stage::portals) != stages.end());
    for (int k = 0; k < 4; ++k) {
        const PipelineResult& a = w.frame();
        const PipelineResult& c = every.frame();
        if (!w.error().empty()) break;  // walked out of the rooms
        CHECK(hsr::analysis::lost_front_pixels(w.scene(), a.frame, c.frame) == 0);
        w.walk(1, 0), every.walk(1, 0);
    }
    for (int k = 0; k < 400; ++k) w.walk(1, 0);  // far out of the plan
    (void)w.frame();
    CHECK((w.error().empty() || w.last().kept.empty()));  // a frame, or a reason (never a crash)
}
