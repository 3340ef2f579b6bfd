// SPDX-License-Identifier: MIT
// The BSP view folded from the machine's events shows exactly the tree the build returns and the order the
// traversal returns; seek(k) equals the fold of [0, k) on the BSP lessons' traces.
#include <random>

#include "bsp/bsp_scene.h"
#include "catch.h"
#include "scene/load_scene.h"
#include "scene/save_scene.h"
#include "state/bsp_session.h"
#include "state/bsp_view.h"
#include "state/families.h"
#include "state/lesson.h"

using namespace hsr::algo;
using namespace hsr::viz;

namespace {

BspJob random_job(std::mt19937_64& rng, bool two_d) {
    std::uniform_real_distribution<double> at(-5, 5), r(-2, 2);
    BspJob job;
    job.options.splitter = SplitterRule::balanced;
    for (int i = 0; i < 25; ++i) {
        const Vec3 c(at(rng), at(rng), two_d ? 0 : at(rng) - 10);
        if (two_d) job.polygons.push_back({i + 1, {c + Vec3(r(rng), r(rng), 0), c + Vec3(r(rng), r(rng), 0)}});
        else
            job.polygons.push_back({i + 1, {c + Vec3(r(rng), r(rng), r(rng)), c + Vec3(r(rng), r(rng), r(rng)),
                                            c + Vec3(r(rng), r(rng), r(rng))}});
    }
    job.eye = Vec3(0.5, 0.25, 0);
    return job;
}

}  // namespace

TEST_CASE("the BSP view folded from the events is the tree and the order the machines return", "[state][bsp]") {
    const bool two_d = GENERATE(false, true);
    std::mt19937_64 rng(two_d ? 2 : 3);
    const BspJob job = random_job(rng, two_d);
    const BspTree tree = build_bsp(job.polygons, job.options).run_to_end();
    const auto order = traverse_bsp(&tree, job.eye).run_to_end();

    BspView view = initial_view(job);
    auto machine = bsp_scene(job);
    for (const auto& e : machine) reduce(view, e);
    REQUIRE(tree.splits > 0);
    REQUIRE(view.polygons.size() == tree.polygons.size());
    for (std::size_t i = 0; i < tree.polygons.size(); ++i) {
        INFO("polygon " << i);
        CHECK(view.polygons[i].label == tree.polygons[i].label);
        CHECK(view.polygons[i].source == tree.polygons[i].source);
        CHECK(*view.polygons[i].vertices == tree.polygons[i].vertices);
    }
    REQUIRE(view.nodes.size() == tree.nodes.size());
    for (std::size_t n = 0; n < tree.nodes.size(); ++n) {
        CHECK(view.nodes[n].front == tree.nodes[n].front);
        CHECK(view.nodes[n].back == tree.nodes[n].back);
        CHECK(view.nodes[n].plane == tree.nodes[n].plane);
        CHECK(view.nodes[n].eye_side.has_value());
    }
    CHECK(view.splits == int(tree.splits));
    for (std::size_t k = 0; k < order.size(); ++k) CHECK(view.polygons[std::size_t(order[k])].drawn == int(k + 1));
    CHECK(machine.result() == order);
}

TEST_CASE("seek(k) equals a fold of the first k events on the BSP lessons", "[state][bsp][player]") {
    for (const char* file : {"04_bsp_build.toml", "05_bsp_traversal.toml"}) {
        INFO(file);
        const Lesson lesson = load_lesson(data_dir() + "/lessons/" + file);
        const BspJob job = bsp_job(lesson.scene, SplitterRule::first);
        std::vector<BspView> folds{initial_view(job)};
        for (const auto& e : bsp_scene(job)) {
            folds.push_back(folds.back());
            reduce(folds.back(), e);
        }
        BspSession::PlayerType player(bsp_scene(job), initial_view(job), {.min_keyframe_interval = 4});
        player.seek_end();
        for (std::size_t k = folds.size(); k-- > 0;) {
            player.seek(k);
            const BspView& a = player.view();
            const BspView& b = folds[k];
            REQUIRE(labels(a) == labels(b));
            REQUIRE(a.current_node == b.current_node);
            REQUIRE(a.current_polygon == b.current_polygon);
            REQUIRE(a.drawn == b.drawn);
            REQUIRE(a.nodes.size() == b.nodes.size());
        }
        BspSession session(lesson);
        session.seek_end();
        CHECK(session.at_end());
        CHECK_FALSE(session.narration().empty());
    }
}

TEST_CASE("moving the eye reruns the traversal from the new eye and keeps the step", "[state][bsp]") {
    BspSession session(load_lesson(data_dir() + "/lessons/04_bsp_build.toml"));
    session.seek_end();
    const std::size_t end = session.cursor();
    session.seek(end - 3);
    const Vec3 eye(0.5, 3, 7);  // across the line of segment 1 (y = 1); z is dropped in 2D
    session.move_eye(eye);
    CHECK(session.cursor() == end - 3);
    session.seek_end();
    CHECK(session.cursor() == end);  // the build is the same, and a traversal has one event per polygon

    const BspJob job = bsp_job(session.lesson().scene, SplitterRule::first);
    const BspTree tree = build_bsp(job.polygons, job.options).run_to_end();
    const auto order = traverse_bsp(&tree, Vec3(eye.x, eye.y, 0)).run_to_end();
    for (std::size_t k = 0; k < order.size(); ++k)
        CHECK(session.view().polygons[std::size_t(order[k])].drawn == int(k + 1));
    CHECK(session.view().eye == Vec3(0.5, 3, 0));
    CHECK(session.view().nodes[0].eye_side == Side::front);  // above the line y = 1 now
}

TEST_CASE("dragging a segment's end reruns the build, keeps the step, undoes, redoes and saves", "[state][bsp][editing]") {
    BspSession session(load_lesson(data_dir() + "/lessons/04_bsp_build.toml"));
    const BspJob original = session.job();
    session.seek(5);
    const Vec3 to = original.polygons[0].vertices[1] + Vec3(0.5, 2.0, 0);
    session.move_vertex(0, 1, to + Vec3(0, 0, 3));  // a 2D scene: z is dropped
    CHECK(session.job().polygons[0].vertices[1] == to);
    CHECK(session.cursor() == 5);
    session.seek_end();
    // the machine ran on the edited input: its first polygon is where the drag left it
    const BspTree tree = build_bsp(session.job().polygons, session.job().options).run_to_end();
    CHECK(tree.polygons[0].vertices[1] == to);
    // one more move of the same vertex is the same drag: one undo brings the original back
    session.move_vertex(0, 1, to + Vec3(0.1, 0, 0));
    CHECK(session.undo());
    CHECK(session.job().polygons[0].vertices == original.polygons[0].vertices);
    CHECK_FALSE(session.undo());
    CHECK(session.redo());
    CHECK(session.job().polygons[0].vertices[1] == to + Vec3(0.1, 0, 0));
    // the edited scene saves and loads back with the moved segment
    const Scene saved = load_scene_text("edited.toml", scene_toml(session.edited_scene()));
    const auto seg = std::find_if(saved.segments.begin(), saved.segments.end(), [&](const SceneSegment& s) { return s.id == original.polygons[0].id; });
    REQUIRE(seg != saved.segments.end());
    CHECK(Vec3(seg->b) == to + Vec3(0.1, 0, 0));
    // a segment dragged to no length is not an edit
    session.move_vertex(0, 1, session.job().polygons[0].vertices[0]);
    CHECK(session.job().polygons[0].vertices[1] == to + Vec3(0.1, 0, 0));
}

TEST_CASE("adding and deleting segments reruns the build, undoes, redoes and saves", "[state][bsp][editing]") {
    BspSession session(load_lesson(data_dir() + "/lessons/04_bsp_build.toml"));
    const std::size_t n = session.job().polygons.size();
    session.seek(4);
    // a new segment across the whole scene: the next free id, and the tree splits more
    const std::size_t splits_before = std::size_t(build_bsp(session.job().polygons, session.job().options).run_to_end().splits);
    REQUIRE(session.add_segment({-20, 0.5, 2}, {20, 0.7, -1}));
    REQUIRE(session.job().polygons.size() == n + 1);
    const BspInput& added = session.job().polygons.back();
    CHECK(added.vertices[0] == Vec3(-20, 0.5, 0));  // in the plane z = 0
    std::int32_t largest = 0;
    for (std::size_t k = 0; k < n; ++k) largest = std::max(largest, session.job().polygons[k].id);
    CHECK(added.id == largest + 1);
    CHECK(session.cursor() == 4);
    CHECK(std::size_t(build_bsp(session.job().polygons, session.job().options).run_to_end().splits) > splits_before);
    CHECK_FALSE(session.add_segment({1, 1, 0}, {1, 1, 0}));  // no length: not an edit
    // delete the first input: the others stay, in order
    const std::int32_t second = session.job().polygons[1].id;
    REQUIRE(session.delete_input(0));
    CHECK(session.job().polygons.size() == n);
    CHECK(session.job().polygons[0].id == second);
    // saved: the deleted segment is gone, the added one is there with a colour
    Scene saved = load_scene_text("edited.toml", scene_toml(session.edited_scene()));
    CHECK(saved.segments.size() == n);
    const std::int32_t deleted = BspSession(load_lesson(data_dir() + "/lessons/04_bsp_build.toml")).job().polygons[0].id;
    CHECK(std::none_of(saved.segments.begin(), saved.segments.end(), [&](const SceneSegment& s) { return s.id == deleted; }));
    CHECK(std::any_of(saved.segments.begin(), saved.segments.end(), [&](const SceneSegment& s) { return s.id == largest + 1; }));
    // undo twice: the original inputs; redo: the added segment again
    CHECK(session.undo());
    CHECK(session.undo());
    CHECK(session.job().polygons.size() == n);
    CHECK(session.job().polygons[0].id != second);
    CHECK(session.redo());
    CHECK(session.job().polygons.size() == n + 1);
    // the last input cannot go: a tree needs something to split
    while (session.job().polygons.size() > 1) REQUIRE(session.delete_input(0));
    CHECK_FALSE(session.delete_input(0));
    CHECK(session.job().polygons.size() == 1);
}

TEST_CASE("the tree's figures follow an edit", "[state][bsp][editing]") {
    BspSession session(load_lesson(data_dir() + "/lessons/04_bsp_build.toml"));
    const std::size_t before = session.stats().polygons_in;
    REQUIRE(session.add_segment({-20, 0.5, 0}, {20, 0.7, 0}));
    CHECK(session.stats().polygons_in == before + 1);
    CHECK(session.stats().splits == build_bsp(session.job().polygons, session.job().options).run_to_end().splits);
}

TEST_CASE("the BSP tree box tells the build's totals only once the player has seen it built", "[bsp][view]") {
    // lesson 05 opens on its first question, "How many splits does the build make?": the box must not answer it
    auto session = hsr::viz::make_session(hsr::viz::load_lesson(HSR_SOURCE_DIR "/lessons/05_bsp_traversal.toml"));
    auto* bsp = session.get_if<hsr::viz::BspSession>();
    REQUIRE(bsp);
    session->seek(6);  // where the window opens it (its first chapter's question), mid-build
    REQUIRE_FALSE(bsp->view().built);
    const std::string building = hsr::viz::tree_summary(*bsp);
    CHECK(building.find("so far") != std::string::npos);
    CHECK(building.find("in the tree after") == std::string::npos);
    CHECK(building.find(std::to_string(bsp->view().splits) + " split") != std::string::npos);  // what the steps showed
    session->seek_end();
    REQUIRE(bsp->view().built);
    CHECK(hsr::viz::tree_summary(*bsp).find("in the tree after " + std::to_string(bsp->stats().splits) + " split") != std::string::npos);
}
