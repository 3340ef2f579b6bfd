// SPDX-License-Identifier: MIT
// Cells-and-portals lessons: the PVS view folds to the machine's matrix, the runtime view to its drawn set; seeking
// equals folding; dragging the eye reruns the traversal from the new place.
#include "catch.h"
#include "state/portal_session.h"

using namespace hsr::viz;

namespace {

Lesson lesson(const char* file, const char* algorithm) {
    Lesson l = load_lesson(std::string(HSR_SOURCE_DIR "/lessons/") + file);
    l.algorithm = *hsr::algo::find_algorithm(algorithm);
    return l;
}

}  // namespace

TEST_CASE("the PVS lesson folds to the matrix and stab trees the machine builds", "[state][portals]") {
    PvsSession s(lesson("18_portals_pvs.toml", "portal_pvs"));
    s.seek_end();
    CHECK(s.view().done);
    CHECK(s.view().matrix == s.view().world->pvs.matrix);
    // the stab tree folded for the last cell is the machine's
    const auto& tree = s.view().tree;
    const auto& want = s.view().world->pvs.trees[std::size_t(s.view().source)];
    REQUIRE(tree.size() == want.size());
    for (std::size_t i = 0; i < tree.size(); ++i) {
        CHECK(tree[i].cell == want[i].cell);
        CHECK(tree[i].parent == want[i].parent);
    }
}

TEST_CASE("seeking a portal_render lesson equals folding it, and its drawn set is the machine's", "[state][portals]") {
    PortalRenderSession s(lesson("19_portals_render.toml", "portal_render"));
    PortalRenderSession fresh(lesson("19_portals_render.toml", "portal_render"));
    s.seek_end();
    const std::size_t n = s.cursor();
    REQUIRE(s.view().done);
    const auto& m = s.view().world->model;
    const auto result = hsr::algo::portal_render(&m, &s.view().world->bsp, &s.view().world->pvs, m.camera).run_to_end();
    for (std::size_t k = 0; k < m.polygons.size(); ++k) CHECK((s.view().fate[k] == PolygonFate::drawn) == (result.drawn[k] != 0));
    CHECK(s.view().visits == 3);  // E, D, A: the lecture's runtime example
    for (std::size_t k = 0; k <= n; ++k) {
        s.seek(k);
        INFO("step " << k);
        REQUIRE(s.view().fate == fresh.view().fate);
        REQUIRE(s.view().path == fresh.view().path);
        REQUIRE(s.view().passed.size() == fresh.view().passed.size());
        REQUIRE(s.view().cell == fresh.view().cell);
        if (k < n) fresh.micro_step();
    }
}

TEST_CASE("the way shown is the way to the cell being visited: after a return, the narrowing of the new way only", "[state][portals]") {
    PortalRenderSession s(lesson("20_portals_bounding_box.toml", "portal_render"));
    s.seek_end();
    const auto& v = s.view();
    const auto& m = v.world->model;
    // H → R first, then back in H, H → T: the last way is H, T with the one narrowing into T
    REQUIRE(v.path.size() == 2);
    CHECK(m.cells[v.path[1]].name == "T");
    REQUIRE(v.passed.size() == 1);
    CHECK(m.cells[m.portals[v.passed[0].portal].to].name == "T");
    CHECK(v.passed[0].section.size() >= 3);
}

TEST_CASE("dragging the eye into another cell reruns portal_render from there", "[state][portals]") {
    PortalRenderSession s(lesson("19_portals_render.toml", "portal_render"));
    s.seek_end();
    CHECK(s.view().eye_cell == 4);  // E
    s.move_eye({5.0, 5.0});         // into B
    s.seek_end();
    CHECK(s.view().world->model.cells[std::size_t(s.view().eye_cell)].name == "B");
    CHECK(s.view().camera.eye.x == 5.0);
    CHECK(s.view().camera.eye.z == -5.0);
}

TEST_CASE("lesson 20's views name the polygons its questions ask about, and draw the exact frustum beside the box", "[state][portals]") {
    // The teacher's report: lesson 20 asked about polygon 915 and crate 903, neither labelled in the picture, and
    // showed only the bounding-box frustum it is about.
    PortalRenderSession s(load_lesson(HSR_SOURCE_DIR "/lessons/20_portals_bounding_box.toml"));
    const PortalView& v = s.view();
    const auto id_of = [&](std::uint32_t k) { return v.world->model.polygons[k].id; };
    const auto names = [&](std::int32_t id) {
        const auto n = named_polygons(v);
        return std::any_of(n.begin(), n.end(), [&](std::uint32_t k) { return id_of(k) == id; });
    };
    bool asked_915 = false, shown_903 = false, wider = false;
    while (!s.at_end()) {
        s.micro_step();
        CHECK(named_polygons(v).size() <= 2);  // the last decided and the next: no pile of labels
        if (v.cell == 1 && v.polygon < 0) asked_915 = asked_915 || names(915);  // R entered, its first wall next
        if (v.polygon >= 0 && id_of(std::uint32_t(v.polygon)) == 903) shown_903 = shown_903 || names(903);
        for (const auto& n : v.passed) wider = wider || wider_than_exact(n, v.camera);
    }
    CHECK(asked_915);
    CHECK(shown_903);
    CHECK(wider);  // the window's box frustum is wider than the exact one: both are drawn
    CHECK(named_polygons(v).empty());  // at the end
}

TEST_CASE("an exact portal frustum is not drawn twice", "[state][portals]") {
    PortalRenderSession s(lesson("20_portals_bounding_box.toml", "portal_render"));
    s.seek_end();
    const PortalView& v = s.view();
    s.seek(16);  // in R, through the window
    REQUIRE_FALSE(v.passed.empty());
    for (const auto& n : v.passed) CHECK_FALSE(wider_than_exact(n, v.camera));
}
