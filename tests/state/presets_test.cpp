// SPDX-License-Identifier: MIT
// Presets: each algorithm's extreme cases are the catalogue's files its family answers, and each plays with that
// algorithm; random scenes load, differ by seed and play.
#include <algorithm>

#include "catch.h"
#include "scene/load_scene.h"
#include "scene/toml_reader.h"
#include "state/lesson.h"
#include "state/presets.h"
#include "state/presets.h"
#include "state/families.h"

using namespace hsr::viz;

namespace {

std::vector<std::string> names(const std::vector<Preset>& p) {
    std::vector<std::string> n;
    for (const Preset& x : p) n.push_back(x.name);
    return n;
}

bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

}  // namespace

TEST_CASE("each algorithm's presets are the extreme cases its family answers, and they play", "[state][presets]") {
    const std::string dir = data_dir() + "/assets/scenes/extreme";
    const auto clip = names(extreme_presets(*hsr::algo::find_algorithm("liang_barsky"), dir));
    CHECK(has(clip, "Segment on a corner"));
    CHECK(has(clip, "Denormals"));
    CHECK_FALSE(has(clip, "Cyclic overlap"));
    const auto sort = names(extreme_presets(*hsr::algo::find_algorithm("depth_sort"), dir));
    CHECK(has(sort, "Cyclic overlap"));
    CHECK(has(sort, "A concave polygon"));
    CHECK_FALSE(has(sort, "Segment on a corner"));
    CHECK(has(names(extreme_presets(*hsr::algo::find_algorithm("zbuffer_fill"), dir)), "Z-fighting at 16 bits"));
    CHECK(has(names(extreme_presets(*hsr::algo::find_algorithm("portal_pvs"), dir)), "A grazing sightline"));
    CHECK(has(names(extreme_presets(*hsr::algo::find_algorithm("backface_view_vector"), dir)), "Faces seen edge-on"));
    CHECK(extreme_presets(*hsr::algo::find_algorithm("z_merge"), dir).empty());
    CHECK(extreme_presets(*hsr::algo::find_algorithm("depth_sort"), "/no/such/folder").empty());

    // every preset of every algorithm plays with it, or is refused with the reason its promise gives
    for (const hsr::algo::AlgorithmInfo& a : hsr::algo::algorithms())
        for (const Preset& p : extreme_presets(a, dir)) {
            INFO(a.id << " on " << p.file);
            try {
                auto session = make_session(load_lesson(p.file, std::string(a.id)));
                session->prefetch(prefetch_events);
                CHECK(session->known() > 0);
            } catch (const std::exception& e) {
                CHECK(std::string(e.what()).find("not convex") != std::string::npos);
            }
        }
}

TEST_CASE("random scenes: one per family, different seeds differ, and they play", "[state][presets]") {
    for (const hsr::algo::AlgorithmInfo& a : hsr::algo::algorithms()) {
        INFO(a.id);
        const auto one = random_scene_toml(a, a.id == "bsp_build", 1), two = random_scene_toml(a, a.id == "bsp_build", 2);
        if (std::holds_alternative<hsr::algo::ZMergeMachine>(a.machine)) {
            CHECK_FALSE(one);
            continue;
        }
        REQUIRE(one);
        CHECK(*one != *two);
        const hsr::algo::Scene s = hsr::algo::load_scene_text("random.toml", *one);
        CHECK(s.name.find("seed 1") != std::string::npos);
        auto session = make_session(read_lesson(hsr::algo::TomlReader("random.toml", *one), std::string(a.id)));
        session->prefetch(prefetch_events);
        CHECK(session->known() > 3);
    }
}

TEST_CASE("the window's report measures the family of the algorithm being played", "[state][report]") {
    const std::string scenes = data_dir() + "/assets/scenes";
    for (const auto& [id, family] : {std::pair{"liang_barsky", "clipping"}, std::pair{"scan_line", "zbuffer"},
                                     std::pair{"depth_sort", "hsr"}, std::pair{"portal_render", "portals"},
                                     std::pair{"backface_view_vector", "culling"}}) {
        INFO(id);
        hsr::analysis::Progress progress;
        const auto rows = family_report(*hsr::algo::find_algorithm(id), scenes, &progress);
        REQUIRE_FALSE(rows.empty());
        for (const auto& r : rows) CHECK(r.family == family);
        // the progress bar ends full, not short of it nor past it: each family plans the timed runs it makes
        CHECK(progress.planned > 0);
        CHECK(progress.done == progress.planned);
        CHECK(progress.fraction() == 1.f);
    }
}

TEST_CASE("a cancelled report stops before its next timed run", "[state][report]") {
    hsr::analysis::Progress progress;
    progress.cancel = true;
    CHECK_THROWS_AS(family_report(*hsr::algo::find_algorithm("depth_sort"), data_dir() + "/assets/scenes", &progress),
                    hsr::analysis::MeasurementCancelled);
    CHECK(progress.done == 0);
}
