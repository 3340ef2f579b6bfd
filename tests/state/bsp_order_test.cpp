// SPDX-License-Identifier: MIT
// DisplayBSP front to back and the insertion order, as the window's BSP box reaches them: front to back visits
// the tree in exactly the opposite order and, painting each polygon only where nothing is yet, ends on the same
// picture; another insertion order builds another tree that shows the same scene.
#include <algorithm>

#include "bsp/bsp_scene.h"
#include "catch.h"
#include "state/bsp_painting.h"
#include "state/bsp_session.h"
#include "state/bsp_view.h"
#include "state/family_facts.h"

using namespace hsr::algo;
using namespace hsr::viz;

namespace {

// A near wall (id 1) in front of a wide far wall (id 2) and a third (id 3) crossing the second's plane.
Scene three_walls() {
    Scene s;
    s.camera.eye = {0, 0, 0}, s.camera.target = {0, 1, 0}, s.camera.up = {0, 0, 1};
    s.camera.fov_y = 60, s.camera.near = 0.1, s.camera.far = 100;
    s.segments.push_back({1, {230, 0, 0}, {-0.5, 2, 0, 1}, {0.5, 2, 0, 1}});
    s.segments.push_back({2, {0, 200, 0}, {-20, 6, 0, 1}, {20, 6, 0, 1}});
    s.segments.push_back({3, {0, 0, 200}, {3, 3, 0, 1}, {6, 9, 0, 1}});
    return s;
}

Lesson lesson_on(Scene scene) {
    Lesson l;
    l.algorithm = *find_algorithm("bsp_traversal");
    l.scene = std::move(scene);
    return l;
}

std::vector<BspPolygonId> order_of(BspJob job) {
    auto machine = bsp_scene(std::move(job));
    for (const auto& e : machine) (void)e;
    return machine.result();
}

Image final_picture(BspSession& s, Viewport size) {
    s.seek_end();
    return bsp_painted_so_far(s.view(), s.edited_scene(), size);
}

double share_differing(const Image& a, const Image& b) {
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.ids.size(); ++i) differ += a.ids[i] != b.ids[i];
    return double(differ) / double(a.ids.size());
}

}  // namespace

TEST_CASE("DisplayBSP front to back draws the back-to-front order reversed", "[state][bsp][order]") {
    for (std::uint32_t seed = 1; seed <= 40; ++seed) {
        const auto scene = random_triangle_scene(seed, false);
        REQUIRE(scene);
        for (SplitterRule rule : {SplitterRule::first, SplitterRule::balanced}) {
            BspJob job = bsp_job(*scene, rule);
            const auto back_to_front = order_of(job);
            job.order = Order::front_to_back;
            auto front_to_back = order_of(job);
            std::reverse(front_to_back.begin(), front_to_back.end());
            CHECK(front_to_back == back_to_front);
        }
    }
}

TEST_CASE("The BSP box's controls: front to back paints the same picture, nearest first", "[state][bsp][order]") {
    BspSession s(lesson_on(three_walls()));
    const Viewport size{160, 40};
    const Image back_to_front = final_picture(s, size);
    s.set_order(Order::front_to_back);
    CHECK(s.job().order == Order::front_to_back);
    CHECK(s.view().order == Order::front_to_back);
    CHECK(share_differing(final_picture(s, size), back_to_front) == 0);
    // the first wall painted front to back is the nearest, and it is all the picture holds then
    s.seek(0);
    s.player().step_forward_until([](const BspEvent& e) { return std::holds_alternative<PolygonDrawn>(e); });
    const Image first = bsp_painted_so_far(s.view(), s.edited_scene(), size);
    CHECK(first.id(size.width / 2, size.height / 2) == 1);
    CHECK(first.id(2, size.height / 2) == 0);  // the far wall, beside it, is not painted yet
    REQUIRE(s.undo());
    CHECK(s.job().order == Order::back_to_front);
}

TEST_CASE("Another insertion order builds another tree of the same picture", "[state][bsp][order]") {
    for (std::uint32_t seed = 1; seed <= 12; ++seed) {
        const auto scene = random_triangle_scene(seed, false);
        REQUIRE(scene);
        BspSession s(lesson_on(*scene));
        const Viewport size{96, 96};
        const Image given = final_picture(s, size);
        const auto first_input = s.job().polygons.front().id, last_input = s.job().polygons.back().id;
        s.reorder_inputs(BspSession::Insertion::reversed);
        CHECK(s.job().polygons.front().id == last_input);  // the rule "first" splits the root with it now
        CHECK(s.job().polygons.back().id == first_input);
        // the polygons' shared edges may round to another pixel where a split cut them: a few pixels at most
        CHECK(share_differing(final_picture(s, size), given) < 0.01);
        s.reorder_inputs(BspSession::Insertion::shuffled, seed);
        CHECK(share_differing(final_picture(s, size), given) < 0.01);
        s.set_splitter(SplitterRule::fewest_splits);
        CHECK(s.stats().rule == SplitterRule::fewest_splits);
        CHECK(share_differing(final_picture(s, size), given) < 0.01);
    }
}
