// SPDX-License-Identifier: MIT
// One test walks every scene file in assets/scenes and checks its [expect] tables against the machines
// (analysis/expect_check.h); a second holds the catalogue of extreme cases in assets/scenes/extreme to its promises.
#include <algorithm>
#include <filesystem>

#include "catch.h"
#include "analysis/expect_check.h"
#include "scene/load_scene.h"

using namespace hsr::algo;
using hsr::analysis::ExpectOutcome;

namespace {

std::vector<std::string> scene_files(const std::string& dir) {
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
        if (e.path().extension() == ".toml") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

std::size_t expectations(const Scene& s) {
    const Expect& e = s.expect;
    return e.clip.size() + e.bsp.size() + e.cull.size() + e.pvs.size() + e.image.size() + e.rejects.size() + e.horizon.size();
}

}  // namespace

TEST_CASE("every scene file loads and meets its expect table", "[scene][expect]") {
    const auto files = scene_files(HSR_SOURCE_DIR "/assets/scenes");
    REQUIRE(files.size() >= 5);
    for (const std::string& file : files) {
        INFO(file);
        const Scene scene = load_scene(file);
        const auto outcomes = hsr::analysis::check_expectations(scene);
        CHECK(outcomes.size() >= expectations(scene));  // every expectation was checked by some machine
        for (const ExpectOutcome& o : outcomes) {
            INFO(o.what << " at line " << o.line << ": " << o.detail);
            CHECK(o.passed);
        }
    }
}

TEST_CASE("the extreme cases: each states its promise, and keeps it", "[scene][expect][extreme]") {
    const auto files = scene_files(HSR_SOURCE_DIR "/assets/scenes/extreme");
    REQUIRE(files.size() >= 30);
    std::size_t images = 0, clips = 0, rejects = 0;
    for (const std::string& file : files) {
        INFO(file);
        const Scene scene = load_scene(file);
        CHECK(scene.promise.size() > 20);
        CHECK(expectations(scene) >= 1);
        images += scene.expect.image.size(), clips += scene.expect.clip.size(), rejects += scene.expect.rejects.size();
        for (const ExpectOutcome& o : hsr::analysis::check_expectations(scene)) {
            INFO(o.what << " at line " << o.line << ": " << o.detail);
            CHECK(o.passed);
        }
    }
    CHECK(images >= 5);
    CHECK(clips >= 5);
    CHECK(rejects >= 1);
}

TEST_CASE("a broken promise is reported, with the line of the expectation", "[scene][expect][extreme]") {
    const Scene s = load_scene_text("broken.toml", R"(
[camera]
eye = [0, 0, 10]
[[polygons]]
id = 1
vertices = [[-1, -1, 0], [1, -1, 0], [1, 1, 0]]
[[polygons]]
id = 2
vertices = [[-1, -1, 0], [1, 1, 0], [-1, 1, 0], [-0.5, 0.2, 0]]
[[expect.image]]
algorithm = "zbuffer"
max_differing = 0
visible = [1, 7]
[[expect.rejects]]
algorithm = "bsp"
message = "polygon 2 is not convex"
[[expect.rejects]]
algorithm = "depth-sort"
message = "polygon 1 is not convex"
)");
    const auto outcomes = hsr::analysis::check_expectations(s);
    REQUIRE(outcomes.size() == 3);
    CHECK_FALSE(outcomes[0].passed);  // id 7 is in no polygon (and the z-buffer refuses the concave one)
    CHECK(outcomes[0].line == 10);
    CHECK(outcomes[1].passed);
    CHECK_FALSE(outcomes[2].passed);  // the message names polygon 2, not the 1 expected
    CHECK(outcomes[2].detail.rfind("refused: polygon 2 is not convex", 0) == 0);
    CHECK(outcomes[2].detail.find("expected a message") != std::string::npos);
}
