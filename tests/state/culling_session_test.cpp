// SPDX-License-Identifier: MIT
// Culling lessons: each view folded to the end holds what its machine returns; seeking equals folding.
#include "catch.h"
#include "state/families.h"

using namespace hsr::viz;
using namespace hsr::algo;

namespace {

std::vector<std::uint8_t> kept_of(const CullingView& v) {
    std::vector<std::uint8_t> k;
    for (PrimitiveMark m : v.primitives) k.push_back(m == PrimitiveMark::kept);
    return k;
}

}  // namespace

TEST_CASE("each culling lesson folds to its machine's answer", "[state][culling]") {
    const char* files[] = {"22_culling_frustum.toml", "23_culling_detail.toml", "24_culling_occluders.toml", "25_culling_hiz.toml"};
    for (const char* file : files) {
        INFO(file);
        const Lesson lesson = load_lesson(std::string(HSR_SOURCE_DIR "/lessons/") + file);
        const FamilySession session = make_session(lesson);
        session->seek_end();
        const CullingLesson& lessonview = session.visit([](auto& s) -> const CullingLesson& {
            if constexpr (std::is_base_of_v<CullingLesson, std::decay_t<decltype(s)>>) return s;
            else throw std::logic_error("not a culling lesson");
        });
        const CullingView& v = lessonview.culling_view();
        REQUIRE(v.done);
        const auto& w = *v.world;
        std::vector<std::uint8_t> want;
        if (lessonview.culling_machine() == CullingMachine::frustum) want = cull_hierarchy(&w.hierarchy, w.scene.camera).run_to_end().kept;
        if (lessonview.culling_machine() == CullingMachine::detail)
            want = cull_hierarchy(&w.hierarchy, w.scene.camera, {.frustum = false, .detail_pixels = w.detail_pixels, .viewport_height = lesson.grid.height})
                       .run_to_end()
                       .kept;
        if (lessonview.culling_machine() == CullingMachine::occluders) want = occlusion_cull(&w.scene, &w.hierarchy, {.max_occluders = 4}).run_to_end().kept;
        if (lessonview.culling_machine() == CullingMachine::hiz) want = hiz_render(&w.scene, &w.hierarchy, w.zbuffer).run_to_end().rendered;
        CHECK(kept_of(v) == want);
        CHECK(v.kept + v.left_out == w.scene.polygons.size());
    }
}

TEST_CASE("seeking a culling lesson equals folding it from the start", "[state][culling]") {
    const Lesson lesson = load_lesson(HSR_SOURCE_DIR "/lessons/25_culling_hiz.toml");
    const auto s = std::make_unique<HizSession>(lesson), fresh = std::make_unique<HizSession>(lesson);
    s->seek_end();
    const std::size_t n = s->cursor();
    const CullingView& a = s->view();
    const CullingView& b = fresh->view();
    for (std::size_t k = 0; k <= n; k += 7) {
        s->seek(k);
        while (fresh->cursor() < k) fresh->micro_step();
        INFO("step " << k);
        REQUIRE(a.nodes == b.nodes);
        REQUIRE(a.primitives == b.primitives);
        REQUIRE(a.rendered == b.rendered);
    }
}

TEST_CASE("the Hi-Z lesson's Z-pyramid is built from the depth the machine itself rendered", "[state][culling]") {
    const Lesson lesson = load_lesson(HSR_SOURCE_DIR "/lessons/25_culling_hiz.toml");
    HizSession s(lesson);
    const CullingView& v = s.view();
    const std::vector<std::uint32_t> cleared = rendered_depth(v);
    REQUIRE(cleared.size() == std::size_t(v.world->zbuffer.viewport.width) * std::size_t(v.world->zbuffer.viewport.height));
    s.seek_end();
    const HizResult r = hiz_render(&v.world->scene, &v.world->hierarchy, v.world->zbuffer).run_to_end();
    CHECK(rendered_depth(v) == r.buffers.depth);
    CHECK(rendered_depth(v) != cleared);
}
