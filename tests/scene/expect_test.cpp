// One test walks every scene file in assets/scenes and checks its [expect] table against every clipping machine
// that clips its primitives.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "catch.h"
#include "bsp/bsp_scene.h"
#include "clipping/clip_scene.h"
#include "culling/backface.h"
#include "portals/pvs.h"
#include "scene/load_scene.h"

using namespace hsr::algo;

namespace {

bool near(const Vec4& a, const Vec4& b) {
    for (int i = 0; i < 4; ++i)
        if (std::fabs(a[i] - b[i]) > 1e-12 * std::max(1.0, std::fabs(b[i]))) return false;
    return true;
}

// Polygons may start at any vertex: compare as cycles.
bool same_cycle(const std::vector<Vec4>& got, const std::vector<Vec4>& want) {
    if (got.size() != want.size()) return false;
    for (std::size_t shift = 0; shift < got.size(); ++shift) {
        bool all = true;
        for (std::size_t i = 0; i < got.size() && all; ++i) all = near(got[(i + shift) % got.size()], want[i]);
        if (all) return true;
    }
    return got.empty();
}

std::vector<std::string> scene_files() {
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(HSR_SOURCE_DIR "/assets/scenes"))
        if (e.path().extension() == ".toml") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

TEST_CASE("every scene file loads and meets its expect table", "[scene][expect]") {
    const auto files = scene_files();
    REQUIRE(files.size() >= 5);
    for (const std::string& file : files) {
        INFO(file);
        const Scene scene = load_scene(file);
        int checked = 0;
        for (const ClipAlgorithm algorithm :
             {ClipAlgorithm::cohen_sutherland, ClipAlgorithm::liang_barsky, ClipAlgorithm::sutherland_hodgman}) {
            INFO("algorithm " << int(algorithm));
            const auto answers = clip_scene(clip_job(scene), algorithm).run_to_end();
            for (const ExpectClip& x : scene.expect.clip) {
                const auto it = std::find_if(answers.begin(), answers.end(), [&](auto& a) { return a.id == x.id; });
                if (it == answers.end()) continue;  // not a primitive this algorithm clips
                INFO("expect at line " << x.line << ", id " << x.id);
                CHECK(std::string(to_string(it->outcome)) == x.outcome);
                if (x.vertices) CHECK(same_cycle(it->vertices, *x.vertices));
                ++checked;
            }
        }
        CHECK(checked >= int(scene.expect.clip.size()));  // every expectation was checked by some machine

        for (const ExpectCull& x : scene.expect.cull) {
            INFO("expect.cull at line " << x.line);
            for (const BackfaceTest test :
                 {BackfaceTest::view_vector, BackfaceTest::plane_equation, BackfaceTest::screen_winding}) {
                const std::string name = test == BackfaceTest::view_vector      ? "view_vector"
                                         : test == BackfaceTest::plane_equation ? "plane_equation"
                                                                                : "screen_winding";
                if (x.test && *x.test != name) continue;
                INFO("test " << name);
                CHECK(cull_back_faces(faces_of(scene), scene.camera, test).run_to_end() == x.kept);
            }
        }

        for (const ExpectBsp& x : scene.expect.bsp) {
            INFO("expect.bsp at line " << x.line << ", splitter " << x.splitter);
            const SplitterRule rule = x.splitter == "first"           ? SplitterRule::first
                                      : x.splitter == "balanced"      ? SplitterRule::balanced
                                      : x.splitter == "fewest-splits" ? SplitterRule::fewest_splits
                                                                      : SplitterRule::weighted;
            BspJob job = bsp_job(scene, rule);  // as a lesson builds it: polygons, or a 2D scene's segments
            const BspTree tree = build_bsp(std::move(job.polygons), job.options).run_to_end();
            if (x.splits) CHECK(int(tree.splits) == *x.splits);
            if (x.order) {
                std::vector<SceneId> painted;
                for (BspPolygonId p : traverse_bsp(&tree, *x.eye).run_to_end())
                    painted.push_back(tree.polygons[std::size_t(p)].source);
                CHECK(painted == *x.order);
            }
        }

        if (!scene.expect.pvs.empty()) {
            const CellModel model = cell_model(scene);
            const Pvs pvs = build_pvs(&model).run_to_end();
            for (const ExpectPvs& x : scene.expect.pvs) {
                INFO("expect.pvs at line " << x.line << ", cell " << x.cell);
                const auto named = [&](const std::string& name) {
                    return std::uint32_t(std::find_if(model.cells.begin(), model.cells.end(), [&](const Cell& c) { return c.name == name; }) -
                                         model.cells.begin());
                };
                std::vector<std::string> got, want = x.visible;
                for (std::uint32_t c : pvs.row(named(x.cell))) got.push_back(model.cells[c].name);
                std::sort(want.begin(), want.end());
                std::sort(got.begin(), got.end());
                CHECK(got == want);
            }
        }
    }
}
