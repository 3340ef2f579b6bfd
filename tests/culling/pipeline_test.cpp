// SPDX-License-Identifier: MIT
// The culling pipeline: the generated scenes are closed and near their size; after back-face, frustum, occluders
// and the hierarchical z-buffer the image is that of rendering every primitive; each stage leaves out something
// on the scene built to show it; and an object hidden only by two occluders together is passed on (the partial
// occlusion problem), though the z-buffer then hides it.
#include <algorithm>
#include <random>

#include "catch.h"
#include "analysis/lost_pixels.h"
#include "culling/occluders.h"
#include "culling/pipeline.h"
#include "portals/cell_model.h"
#include "scene/generated_scenes.h"
#include "scene/load_scene.h"
#include "scene/polygons_of.h"

using namespace hsr::algo;
using hsr::test::polygons_of;

namespace {

const StageReport& report(const PipelineResult& r, Stage s) {
    return *std::find_if(r.stages.begin(), r.stages.end(), [&](const StageReport& x) { return x.stage == s; });
}

int real_differences(const Scene& s, const FrameDepth& culled, const FrameDepth& all) {
    return int(hsr::analysis::lost_front_pixels(s, culled, all));
}

}  // namespace

TEST_CASE("generated scenes are closed meshes near the size asked for", "[culling][scenes]") {
    for (const Scene& s : {city_scene({.triangles = 1200}), field_scene({.triangles = 1200}), spheres_scene({.triangles = 1200})}) {
        INFO(s.name);
        CHECK(s.polygons.size() >= 800);
        CHECK(s.polygons.size() <= 2000);
        CHECK(enclosed_volume(polygons_of(s)) > 0);  // wound outwards: a closed mesh encloses positive volume
    }
    Scene one;
    SceneId id = 1;
    add_box(one, {0, 0, 0}, {1, 2, 3}, {}, id);
    CHECK(enclosed_volume(polygons_of(one)) == Approx(6));
}

TEST_CASE("culling is conservative: the image after the pipeline is the image of every primitive", "[culling][pipeline]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 6; ++trial) {
        Scene s = trial % 3 == 0 ? city_scene({.triangles = 3000, .seed = std::uint32_t(trial)})
                  : trial % 3 == 1 ? field_scene({.triangles = 3000, .seed = std::uint32_t(trial)})
                                   : spheres_scene({.triangles = 3000, .seed = std::uint32_t(trial)});
        s.camera.target += Vec3(u(rng), u(rng), u(rng)) * 3.0;  // a random turn of the head
        const Viewport vp{96, 72};
        const PipelineResult culled = run_pipeline(s, {.stages = {Stage::back_face, Stage::frustum, Stage::occluders, Stage::hiz}, .viewport = vp});
        const PipelineResult all = run_pipeline(s, {.stages = {}, .viewport = vp});
        INFO(s.name << ", trial " << trial);
        CHECK(real_differences(s, culled.frame, all.frame) == 0);
        CHECK(report(culled, Stage::hse).in < s.polygons.size());
    }
}

TEST_CASE("every stage leaves out something on the scene built to show it", "[culling][pipeline]") {
    const Viewport vp{160, 120};
    SECTION("closed spheres: back-face culling about half") {
        const Scene s = spheres_scene({.triangles = 4000});
        const auto r = run_pipeline(s, {.stages = {Stage::back_face}, .viewport = vp});
        CHECK(report(r, Stage::back_face).left_out > s.polygons.size() * 4 / 10);
        CHECK(report(r, Stage::back_face).left_out < s.polygons.size() * 6 / 10);
    }
    SECTION("a field all round the camera: the frustum most, detail the far small ones") {
        const Scene s = field_scene({.triangles = 20000});
        const auto r = run_pipeline(s, {.stages = {Stage::frustum, Stage::detail}, .viewport = vp, .detail_pixels = 4});
        CHECK(report(r, Stage::frustum).left_out > s.polygons.size() / 2);
        CHECK(report(r, Stage::detail).left_out > 0);
        CHECK_FALSE(report(r, Stage::occluders).ran);
    }
    SECTION("a city from the street: occluders and the hierarchical z-buffer much of what the frustum keeps") {
        const Scene s = city_scene({.triangles = 20000});
        const auto r = run_pipeline(s, {.stages = {Stage::back_face, Stage::frustum, Stage::occluders, Stage::hiz}, .viewport = vp,
                                         .hierarchy = HierarchyKind::bvh});
        CHECK(report(r, Stage::occluders).left_out > 0);
        CHECK(report(r, Stage::hiz).left_out > report(r, Stage::hiz).in / 4);  // hidden behind what the occluders could not cull alone
        CHECK(report(r, Stage::hse).in < s.polygons.size() / 10);
    }
}

TEST_CASE("the partial occlusion problem: hidden by two occluders together, culled by neither", "[culling][occluders]") {
    // Two square walls facing the eye, side by side (meeting at x = 0), and a small box behind the seam
    const auto scene_with = [](std::vector<std::pair<double, double>> walls) {
        Scene s;
        s.camera = {.eye = {0, 1, 10}, .target = {0, 1, 0}, .near = 0.5, .far = 50};
        SceneId id = 1;
        for (const auto& [x0, x1] : walls)
            s.polygons.push_back({id++, {200, 80, 80}, {{x0, -2, 2, 1}, {x1, -2, 2, 1}, {x1, 4, 2, 1}, {x0, 4, 2, 1}}});
        add_box(s, {-0.5, 0.5, -2}, {0.5, 1.5, -1}, {80, 80, 200}, id);
        return s;
    };
    const auto cull = [](const Scene& s) {
        const Hierarchy h = build_hierarchy(polygon_boxes(s), {.kind = HierarchyKind::bvh, .max_primitives = 2}).run_to_end();
        return occlusion_cull(&s, &h, {.max_occluders = 4}).run_to_end();
    };
    const Scene two = scene_with({{-4, 0}, {0, 4}});
    const OcclusionCull c = cull(two);
    CHECK(c.occluders.size() >= 2);  // the walls, and the box's own faces that face the eye
    CHECK(std::count(c.kept.begin() + 2, c.kept.end(), 1) > 0);  // neither wall's frustum holds the box whole
    const PipelineResult r = run_pipeline(two, {.stages = {Stage::occluders}, .viewport = {64, 48}});
    for (SceneId seen : r.frame.image.ids) CHECK(seen <= 2);  // but the z-buffer hides it
    SECTION("one wall as wide as both culls it") {
        const OcclusionCull one = cull(scene_with({{-4, 4}}));
        CHECK(std::count(one.kept.begin() + 1, one.kept.end(), 1) == 0);
        CHECK(one.kept[0] == 1);  // the occluder is not culled by its own frustum
    }
}

TEST_CASE("culling stages by name, and an unknown one named in the error", "[culling][pipeline][errors]") {
    CHECK(parse_stages("back-face,frustum,hiz") == std::vector<Stage>{Stage::back_face, Stage::frustum, Stage::hiz});
    CHECK_THROWS_WITH(parse_stages("frustum,occlusion"), Catch::Contains("\"occlusion\""));
}

TEST_CASE("OBJ meshes load as closed polygons, placed and numbered, and back-face culling halves them", "[culling][meshes]") {
    const Scene s = load_scene(HSR_SOURCE_DIR "/assets/scenes/meshes_demo.toml");
    REQUIRE(s.polygons.size() == 128 + 128 + 6);
    CHECK(s.polygons[0].id == 100);
    CHECK(s.polygons[128].id == 300);
    CHECK(s.polygons.back().id == 505);
    const auto cube = polygons_of(s);
    CHECK(enclosed_volume({cube.end() - 6, cube.end()}) == Approx(1.5 * 1.5 * 1.5));  // scaled, turned, moved: still 3.375
    const auto r = run_pipeline(s, {.stages = {Stage::back_face}, .viewport = {96, 64}});
    CHECK(report(r, Stage::back_face).left_out > s.polygons.size() / 3);
    CHECK(report(r, Stage::back_face).left_out < s.polygons.size() * 2 / 3);
    const auto all = run_pipeline(s, {.stages = {}, .viewport = {96, 64}});
    CHECK(real_differences(s, r.frame, all.frame) == 0);
}

TEST_CASE("a mesh that cannot be read names the scene file, line and field", "[culling][meshes][errors]") {
    CHECK_THROWS_WITH(load_scene_text(HSR_SOURCE_DIR "/assets/scenes/x.toml", "[[meshes]]\nfile = \"meshes/none.obj\"\n"),
                      Catch::Contains("x.toml:2") && Catch::Contains("meshes[0].file") && Catch::Contains("none.obj"));
    CHECK_THROWS_WITH(load_scene_text(HSR_SOURCE_DIR "/assets/scenes/x.toml", "[[meshes]]\nfile = \"meshes/cube.obj\"\nid = 65533\n"),
                      Catch::Contains("ids from 1 to 65535"));
}

TEST_CASE("a floor plan runs through the pipeline with its portals stage, conservatively", "[culling][pipeline][portals]") {
    const Scene plan = load_scene(HSR_SOURCE_DIR "/assets/scenes/cells_lecture.toml");
    const PipelineResult culled = run_pipeline(plan, {.stages = {Stage::back_face, Stage::frustum, Stage::portals}, .viewport = {96, 72}});
    const PipelineResult all = run_pipeline(plan, {.stages = {}, .viewport = {96, 72}});
    CHECK(report(culled, Stage::portals).ran);
    CHECK(report(culled, Stage::portals).left_out > 0);
    const CellModel model = cell_model(plan);
    CHECK(real_differences(model_scene(model), culled.frame, all.frame) == 0);
    // a scene without cells has no portals stage to run
    const PipelineResult city = run_pipeline(city_scene({.triangles = 600}), {.stages = {Stage::portals}, .viewport = {32, 24}});
    CHECK_FALSE(report(city, Stage::portals).ran);
}
