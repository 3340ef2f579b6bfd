// SPDX-License-Identifier: MIT
// Z-buffer lessons: the view folds to the machine's buffers, seeking equals folding, and changing the format or
// near and far reruns the fill and moves the z-fighting the lesson is about.
#include <algorithm>
#include <filesystem>
#include <fstream>

#include "catch.h"
#include "state/zbuffer_session.h"
#include "state/zmerge_session.h"

using namespace hsr::viz;
using namespace hsr::algo;

namespace {

std::unique_ptr<ZBufferSession> open(const char* lesson) {
    return std::make_unique<ZBufferSession>(load_lesson(HSR_SOURCE_DIR "/lessons/" + std::string(lesson)));
}

}  // namespace

TEST_CASE("the z-buffer view folded to the end holds the fill's frame and depth buffers", "[state][zbuffer]") {
    auto s = open("07_zbuffer_fill.toml");
    s->seek_end();
    Scene scene = s->lesson().scene;
    const Viewport grid = s->lesson().grid;
    scene.camera.aspect = double(grid.width) / grid.height;
    const FrameDepth f = zbuffer_fill(project_polygons(scene, grid), zbuffer_options(scene, grid, s->format())).run_to_end();
    CHECK(s->view().owner == f.polygon);
    CHECK(std::vector<std::uint32_t>(s->view().depth.begin(), s->view().depth.end()) == f.depth);
    CHECK(s->view().done);
    CHECK(s->view().written == f.written);
    std::size_t covered = 0;
    for (auto o : f.polygon) covered += o >= 0;
    CHECK(covered > 100);  // all three triangles show
    CHECK(s->pixels_unlike_ray_cast() < 10);  // only edge pixels, no z-fighting at 24 bits
}

TEST_CASE("seeking any step of a z-buffer lesson equals folding its events from the start", "[state][zbuffer]") {
    auto s = open("07_zbuffer_fill.toml");
    s->seek_end();
    const std::size_t n = s->cursor();
    auto fresh = open("07_zbuffer_fill.toml");
    for (std::size_t k = 0; k <= n; k += 37) {
        s->seek(k);
        fresh->seek(0);
        for (std::size_t i = 0; i < k; ++i) fresh->micro_step();
        INFO("step " << k);
        REQUIRE(s->view().owner == fresh->view().owner);
        REQUIRE(s->view().depth == fresh->view().depth);
        REQUIRE(s->view().pixel_x == fresh->view().pixel_x);
        REQUIRE(s->view().span_y == fresh->view().span_y);
    }
}

TEST_CASE("z-fighting comes and goes with the depth format and near", "[state][zbuffer][z-fighting]") {
    auto s = open("08_depth_precision.toml");
    REQUIRE(s->format() == DepthFormat::int16);
    const std::size_t fighting = s->pixels_unlike_ray_cast();
    CHECK(fighting > 50);  // the far square shows through in stripes
    s->seek(500);
    s->set_format(DepthFormat::int24);
    CHECK(s->cursor() == 500);  // the rerun keeps the step
    CHECK(s->pixels_unlike_ray_cast() < 5);
    s->set_format(DepthFormat::int16);
    s->set_range({5, 500});  // move near out: the codes spread over the far distances
    CHECK(s->pixels_unlike_ray_cast() < 5);
    s->set_range({0.05, 500});  // move it in: the squares share every code
    CHECK(s->pixels_unlike_ray_cast() > fighting);
    s->set_range({10, 1});  // not a range: ignored
    CHECK(s->range().near == 0.05);
}

TEST_CASE("a z-buffer lesson with a bad format or grid names the field and line", "[lesson][errors][zbuffer]") {
    const auto dir = std::filesystem::temp_directory_path() / "hsrviz_zbuffer_lesson_test";
    std::filesystem::create_directories(dir);
    const std::string scene = HSR_SOURCE_DIR "/assets/scenes/zbuffer_triangles.toml";
    const auto write = [&](const char* name, const std::string& extra) {
        const auto p = dir / name;
        std::ofstream(p) << "title = \"t\"\nalgorithm = \"zbuffer_fill\"\nscene = \"" << scene << "\"\n" << extra;
        return p.string();
    };
    CHECK_THROWS_WITH(load_lesson(write("f.toml", "format = \"int8\"\n")), Catch::Contains("f.toml:4:") && Catch::Contains("'format'"));
    CHECK_THROWS_WITH(load_lesson(write("g.toml", "grid = [0, 24]\n")), Catch::Contains("g.toml:4:") && Catch::Contains("'grid'"));
    CHECK_THROWS_WITH(load_lesson(write("h.toml", "grid = [32]\n")), Catch::Contains("h.toml:4:") && Catch::Contains("grid"));
}

TEST_CASE("the z-merge lesson's merged image is the z-buffer of the whole scene", "[state][zbuffer][merge]") {
    auto lesson = load_lesson(HSR_SOURCE_DIR "/lessons/12_z_merge.toml");
    REQUIRE(std::holds_alternative<ZMergeMachine>(lesson.algorithm.machine));
    ZMergeSession s(lesson);
    s.seek_end();
    Scene scene = lesson.scene;
    scene.camera.aspect = double(lesson.grid.width) / lesson.grid.height;
    const FrameDepth whole = zbuffer_fill(project_polygons(scene, lesson.grid), zbuffer_options(scene, lesson.grid, lesson.depth_format)).run_to_end();
    CHECK(s.view().merged == whole.polygon);
    CHECK(s.view().from_a_count > 0);
    CHECK(s.view().from_b_count > 0);
    // background: the pixels no polygon of either part covers, not counted as part B's
    CHECK(s.view().background_count == std::size_t(std::count(whole.polygon.begin(), whole.polygon.end(), -1)));
    CHECK(s.view().background_count > 0);
    CHECK(s.view().from_a_count + s.view().from_b_count + s.view().background_count == whole.polygon.size());
}

TEST_CASE("editing in the fat-pixel view: move a vertex on the screen, add and delete polygons, undo, redo", "[state][zbuffer][editing]") {
    ZBufferSession s(load_lesson(data_dir() + "/lessons/07_zbuffer_fill.toml"));
    const std::size_t n = s.edited_scene().polygons.size();
    s.seek(40);
    // a vertex dragged on the screen lands where it was dropped, at the depth it had
    const auto before = s.on_screen(s.edited_scene().polygons[0].vertices[0]);
    REQUIRE(before);
    const glm::dvec2 to(before->x + 1.5, before->y - 2.25);
    REQUIRE(s.move_vertex(0, 0, to));
    const auto after = s.on_screen(s.edited_scene().polygons[0].vertices[0]);
    REQUIRE(after);
    CHECK(after->x == Approx(to.x).margin(1e-9));
    CHECK(after->y == Approx(to.y).margin(1e-9));
    CHECK(after->z == Approx(before->z).margin(1e-12));
    CHECK(s.cursor() == 40);
    // a second move of the same vertex is the same drag: one undo takes both back
    REQUIRE(s.move_vertex(0, 0, to + glm::dvec2(0.5, 0)));
    CHECK(s.undo());
    CHECK(s.on_screen(s.edited_scene().polygons[0].vertices[0])->x == Approx(before->x).margin(1e-9));
    // a triangle added on the screen: in the fill, with the next id; deleted again
    REQUIRE(s.add_triangle({2, 2}, {12, 3}, {6, 10}));
    CHECK(s.edited_scene().polygons.size() == n + 1);
    s.seek_end();
    const SceneId added = s.edited_scene().polygons.back().id;
    CHECK(std::count(s.view().owner.begin(), s.view().owner.end(), std::int32_t(n)) > 20);  // it covers pixels
    CHECK(added > s.edited_scene().polygons[0].id);
    REQUIRE(s.delete_polygon(n));
    CHECK(s.edited_scene().polygons.size() == n);
    CHECK(s.undo());
    CHECK(s.edited_scene().polygons.size() == n + 1);
    CHECK(s.redo());
    CHECK(s.edited_scene().polygons.size() == n);
    // refused: a triangle with no area (three points on a line), a polygon out of range, deleting the last one
    const std::size_t count = s.edited_scene().polygons.size();
    CHECK_FALSE(s.add_triangle({2, 2}, {6, 4}, {10, 6}));
    CHECK(s.edited_scene().polygons.size() == count);
    CHECK_FALSE(s.delete_polygon(99));
    while (s.edited_scene().polygons.size() > 1) REQUIRE(s.delete_polygon(0));
    CHECK_FALSE(s.delete_polygon(0));
}

TEST_CASE("pixels unlike the ray cast with their centre on a shared edge are told apart from depth errors", "[state][zbuffer]") {
    // the fill-rule lesson: six triangles whose edges run through pixel centres; the ray cast counts an edge as
    // inside both triangles, the fill rule gives it to one: every difference is such a tie
    auto fill_rule = open("11_fill_rule.toml");
    CHECK(fill_rule->pixels_unlike_ray_cast() > 0);
    CHECK(fill_rule->unlike_on_edges() == fill_rule->pixels_unlike_ray_cast());
    // z-fighting at 16 bits: differences well inside the polygons, not on their edges
    auto fighting = open("08_depth_precision.toml");
    fighting->set_format(DepthFormat::int16);
    CHECK(fighting->pixels_unlike_ray_cast() > fighting->unlike_on_edges());
}
